#pragma once
// Private: layout of the master-curve tables written at build time by
// tools/generate_master_curves.cpp into <build>/generated/master_curve_data.cpp.

namespace bounce::analytic::detail {

enum MasterQuantity : int {
  cor_overlap_scaled = 0,  ///< e_overlap * kappa^5 in the octaves (saturates at C); e in the small domain
  time_overlap = 1,        ///< scaled contact time, overlap rule
  cor_force = 2,           ///< e, force rule
  time_force = 3,          ///< scaled contact time, force rule
  max_overlap = 4,         ///< scaled maximum overlap (both rules)
  quantity_count = 5,
};

constexpr int small_nodes = 32;        ///< Chebyshev in u = sqrt(kappa), kappa in [0, 1]
constexpr int octave_count = 27;       ///< kappa in [2^k, 2^(k+1)), k = 0 .. 26
constexpr int octave_max_nodes = 32;
constexpr int overlap_octaves = 3;     ///< the overlap rule uses octaves 0..2, then its tail
constexpr double overlap_tail_start = 8.0;
constexpr int tail_nodes = 20;         ///< Phi(z), z = (kappa/8)^(-5/3) in [0, 1]

extern const double small_coefficients[quantity_count][small_nodes];
extern const int octave_nodes[octave_count];
extern const double octave_coefficients[octave_count][quantity_count][octave_max_nodes];
extern const double tail_time_coefficients[tail_nodes];
extern const double tail_cor_constant;  ///< C in e_overlap = C kappa^-5 for kappa >= 8
extern const double fit_error_estimate; ///< largest tail coefficient relative to the leading one

/// Overlap rule: e = 1 + sum_{n>=1} c_n kappa^n, c_1 = -2b and c_2 = (3/5)(2b)^2 exact,
/// the rest fitted to the reference; each with its uncertainty.
constexpr int series_capacity = 8;
extern const int overlap_series_terms;
extern const double overlap_series[series_capacity];
extern const double overlap_series_uncertainty[series_capacity];
/// Force rule: e_force - e_overlap = kappa^{5/2} sum_{n>=0} d_n kappa^n, d_0 = 32/(75 sqrt 5).
extern const int force_series_terms;
extern const double force_series[series_capacity];
extern const double force_series_uncertainty[series_capacity];

}  // namespace bounce::analytic::detail

#pragma once
// K13's dynamic adhesive contact (Krijt et al. 2013, §2.2-3 and appendices B, C):
// the contact radius a and the mutual approach delta are independent variables;
//   m delta'' = -(F_E + F_D),  F_E = (2E*/3R)(3 a delta R - a^3)   K13 (2), (20)
//   F_D = 2 A E* a delta'                                          K13 (19)
//   a' = c f(beta),  beta = G_eff/gamma,  c = E* gamma/(sigma0^2 T_vis)   K13 (14)-(17)
// with sigma0 = gamma/z0 and f the crack law of crack.hpp. The physics lives
// here as plain functions of the state; dynamics/adhesive_collision.hpp
// integrates it.

#include "bounce/models/adhesive_pair.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::models {

/// K13's parameters: an adhesive pair's (adhesive_pair.hpp) and its crack law's.
struct KrijtParameters : AdhesivePair {
  double relaxation_time = 0.0;  ///< T_vis [s]
  double k = 0.02;               ///< ratio of relaxed to instantaneous modulus

  /// c = E* gamma / (sigma0^2 T_vis) = E* z0^2 / (gamma T_vis) [m/s], K13 (16).
  double crack_speed_scale() const;
};

/// K13 after (18): A ~ T_vis / nu^2, nu the Poisson ratio. For unlike bodies we
/// take the nu of the more compliant one (the larger (1 - nu^2)/E); a rigid wall
/// does not deform, so body 1's.
double krijt_dissipative_constant(double relaxation_time, const Pair& pair);

/// K13 (14): beta = G_eff / gamma = E* (a^2 - delta R)^2 / (2 pi a R^2 gamma).
double effective_surface_energy_ratio(const AdhesivePair& p, double contact_radius, double approach);
/// K13 (2) and (19).
double elastic_force(const AdhesivePair& p, double contact_radius, double approach);
double bulk_dissipative_force(const AdhesivePair& p, double contact_radius, double rate);
/// K13 (3) + (6): U_E + U_S.
double contact_energy(const AdhesivePair& p, double contact_radius, double approach);

/// K13 appendix B: at first contact delta = 0 and the contact grows at a crack
/// speed that diverges for beta -> k. The integration starts where G_eff = 1.01 k
/// gamma, i.e. a0 from (B.1); `time` is the time the crack law needs from beta = k
/// to there (quadrature of (16) at delta = 0, ~1e-14 s for ice), and
/// `crack_dissipated` the energy the formation released, -(U_E + U_S)(a0, 0).
/// Singular-perturbation estimate (docs/adhesive.md): when the crack is much faster
/// than the collision it follows the JKR equilibrium with |beta - 1| set by the speed
/// it must keep up with, a ~ a/t_c, through (17): |beta - 1| ~ (phi/0.39)^{1/1.14},
/// phi = a / (c t_c). The extra (hysteresis) loss is then about 2 pi a^2 gamma
/// |beta - 1|; returned relative to the impact energy (1/2) m v^2.
double krijt_hysteresis_estimate(const KrijtParameters& p, double speed);
/// Below this estimate `krijt` is integrated as its fast-crack limit, jkr-viscoelastic:
/// the measured difference there is below the full model's integration error (~1e-8).
constexpr double krijt_reduction_threshold = 1e-11;

/// K13's end: the crack runs away (a' -> -inf) as beta -> 1/k; the contact counts as broken at
/// beta = (1 - krijt_break_margin) / k (the collision engine's default, and the DEM law's).
constexpr double krijt_break_margin = 1e-6;

/// K13's crack law (14)-(17) over one step dt of a DEM code, with the overlap at the step's end:
/// backward Euler in a, a - a_old = dt c f(beta(a, delta)), c of (16), taking the root connected
/// to a_old (above it where the contact grows; where it shrinks, the first one below it). It is
/// stable for any c dt: as c dt -> inf, f(beta) -> 0 and a goes to the JKR equilibrium (the
/// fast-crack limit). `broken`: below a_old no root is met before beta >= (1 - krijt_break_margin)/k
/// and rising as a falls; the crack runs away inside the step and the contact ends (K13's end, as
/// dynamics::integrate_krijt_collision's). Where a^2 < delta R (K13 (14) squares the edge's stress
/// intensity, negative there) the edge closes at the crack law's top speed (docs/decisions.md D22).
struct CrackStep {
  double contact_radius = 0.0;
  bool broken = false;
};
CrackStep krijt_crack_step(const KrijtParameters& p, double contact_radius, double overlap, double dt);
/// The same by BDF2, of second order and as stable (L-stable), from the radii a_old and
/// a_older at the ends of the last two steps, `ratio` = dt / (the step before), <= 2 (BDF2 with
/// variable steps is zero-stable below 1 + sqrt 2): with w = ratio,
///   a - ((1 + w)^2 a_old - w^2 a_older) / (1 + 2w) = ((1 + w) / (1 + 2w)) dt c f(beta(a, delta)).
/// `guess` (> 0): where Newton's iteration starts (default: a_old + ratio (a_old - a_older)).
CrackStep krijt_crack_step(const KrijtParameters& p, double contact_radius, double overlap, double dt,
                           double older_radius, double ratio, double guess = 0.0);

struct InitialContact {
  double contact_radius = 0.0;
  double time = 0.0;
  double crack_dissipated = 0.0;
};
InitialContact krijt_initial_contact(const KrijtParameters& p);
/// Its contact radius alone, a0 of (B.1) at beta = 1.01 k (without the quadrature of the time).
double krijt_formation_radius(const KrijtParameters& p);

/// The overlap (< 0) beyond which beta > (1 - krijt_break_margin)/k for every contact radius:
/// no neck holds there. With d = -delta R, beta is least at a^2 = d/3, where
/// beta = (16 sqrt(3) / 9) E* d^{3/2} / (2 pi R^2 gamma) (K13 (14)).
double krijt_release_overlap(const KrijtParameters& p);

}  // namespace bounce::models

#include "bounce/models/crack.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

namespace bounce::models {

CrackSpeed crack_speed_high(double beta, double k) {  // K13 (16)
  if (beta < 1.0) {
    // f = 0.15 / (beta L), L = ln((1-k)/(1-beta)); dL/dbeta = 1/(1-beta)
    const double l = std::log((1.0 - k) / (1.0 - beta));
    const double f = 0.15 / (beta * l);
    return {f, -f * (1.0 / beta + 1.0 / ((1.0 - beta) * l))};
  }
  if (beta > 1.0) {
    // f = -0.24 beta / L, L = ln((1-k)/(1 - 1/beta)); dL/dbeta = -1/(beta (beta - 1))
    const double l = std::log((1.0 - k) / (1.0 - 1.0 / beta));
    const double f = -0.24 * beta / l;
    return {f, f / beta + f / (l * beta * (beta - 1.0))};
  }
  return {0.0, 0.0};  // (16) tends to 0 at beta = 1 (logarithmically)
}

CrackSpeed crack_speed_low(double beta) {  // K13 (17), k = 0.02
  if (beta < 1.0) {
    const double x = 1.0 / beta - 1.0;  // dx/dbeta = -1/beta^2
    const double p = std::pow(x, 1.116);
    const double f = (0.1035 * x + 0.3421) * p;
    const double dfdx = 0.1035 * p + (0.1035 * x + 0.3421) * 1.116 * p / x;
    return {f, -dfdx / (beta * beta)};
  }
  if (beta > 1.0) {
    const double x = beta - 1.0;
    const double p = std::pow(x, 1.1403);
    const double f = -(0.2112 * x + 0.3939) * p;
    const double dfdx = -(0.2112 * p + (0.2112 * x + 0.3939) * 1.1403 * p / x);
    return {f, dfdx};
  }
  return {0.0, 0.0};
}

namespace {
// C1 blend from `from` (s = 0) to `to` (s = 1) with the smoothstep 3s^2 - 2s^3.
CrackSpeed blend(const CrackSpeed& from, const CrackSpeed& to, double s, double ds_dbeta) {
  const double w = s * s * (3.0 - 2.0 * s);
  const double dw = 6.0 * s * (1.0 - s) * ds_dbeta;
  return {from.value + w * (to.value - from.value),
          from.derivative + w * (to.derivative - from.derivative) + dw * (to.value - from.value)};
}
}  // namespace

namespace {
constexpr double low_band_bottom = 0.31, low_band_top = 3.6;  // where (17) holds alone

// The reference law, K13's at its k = 0.02: (17) on [0.31, 3.6], (16) outside [0.29, 3.7], C1
// blends between.
CrackSpeed reference_piecewise(double beta) {
  constexpr double k = crack_reference_k;
  if (beta <= 0.29 || beta >= 3.7) return crack_speed_high(beta, k);
  if (beta >= low_band_bottom && beta <= low_band_top) return crack_speed_low(beta);
  if (beta < 0.31) return blend(crack_speed_high(beta, k), crack_speed_low(beta), (beta - 0.29) / 0.02, 1.0 / 0.02);
  return blend(crack_speed_low(beta), crack_speed_high(beta, k), (beta - 3.6) / 0.1, 1.0 / 0.1);
}

// Value, slope and curvature of the piecewise law at beta (curvature by a central
// difference of the analytic slope, step 1e-3 of the join's half-width).
struct Jet {
  double f, d1, d2;
};
Jet jet(double beta) {
  const double h = 1e-3 * crack_smoothing_width;
  const CrackSpeed c = reference_piecewise(beta);
  const double d2 = (reference_piecewise(beta + h).derivative - reference_piecewise(beta - h).derivative) / (2 * h);
  return {c.value, c.derivative, d2};
}

// Quintic Hermite interpolation on [x0, x1] matching value, slope and curvature at
// both ends, plus c t^3 (1 - t)^3 (zero value, slope and curvature at both ends)
// with c such that f = 0 at the midpoint: the JKR equilibrium stays at beta = 1.
CrackSpeed join(const Jet& a, const Jet& b, double x0, double x1, double x) {
  const double h = x1 - x0;
  auto hermite = [&](double t) {
    const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
    // Hermite basis for (f0, h f0', h^2 f0'', f1, h f1', h^2 f1'') and their t-derivatives.
    const double h0 = 1 - 10 * t3 + 15 * t4 - 6 * t5, h1 = t - 6 * t3 + 8 * t4 - 3 * t5,
                 h2 = 0.5 * (t2 - 3 * t3 + 3 * t4 - t5), h3 = 10 * t3 - 15 * t4 + 6 * t5,
                 h4 = -4 * t3 + 7 * t4 - 3 * t5, h5 = 0.5 * (t3 - 2 * t4 + t5);
    const double d0 = -30 * t2 + 60 * t3 - 30 * t4, d1 = 1 - 18 * t2 + 32 * t3 - 15 * t4,
                 d2 = 0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4), d3 = 30 * t2 - 60 * t3 + 30 * t4,
                 d4 = -12 * t2 + 28 * t3 - 15 * t4, d5 = 0.5 * (3 * t2 - 8 * t3 + 5 * t4);
    const double value = h0 * a.f + h1 * h * a.d1 + h2 * h * h * a.d2 + h3 * b.f + h4 * h * b.d1 + h5 * h * h * b.d2;
    const double slope = d0 * a.f + d1 * h * a.d1 + d2 * h * h * a.d2 + d3 * b.f + d4 * h * b.d1 + d5 * h * h * b.d2;
    return CrackSpeed{value, slope};  // slope per unit t
  };
  const double c = -64.0 * hermite(0.5).value;  // t^3 (1 - t)^3 = 1/64 at t = 1/2
  const double t = (x - x0) / h, u = t * (1.0 - t);
  const CrackSpeed q = hermite(t);
  return {q.value + c * u * u * u, (q.derivative + c * 3.0 * u * u * (1.0 - 2.0 * t)) / h};
}
// The reference law with the join around beta = 1; the jets at the join's edges computed once.
CrackSpeed reference_law(double beta) {
  const double w = crack_smoothing_width;
  if (std::abs(beta - 1.0) >= w) return reference_piecewise(beta);
  static const Jet below = jet(1.0 - w), above = jet(1.0 + w);
  return join(below, above, 1.0 - w, 1.0 + w, beta);
}

}  // namespace

CrackSpeed crack_speed_function(double beta, double k) {  // K13 (16)-(17) at any k
  const CrackBeta r = reference_beta(beta, k);
  return crack_speed_at_k(reference_law(r.beta), beta, r);
}

bool crack_speed_concave(double beta, double k) {  // K13 (17), carried to k
  if (!(beta > 1.0)) return false;
  const double beta_ref = reference_beta(beta, k).beta;
  return beta_ref >= 1.0 + crack_smoothing_width && beta_ref <= low_band_top;
}

namespace {
// The table's cells: 32 to a binade of x (K13 (17)'s 1/beta - 1 or beta - 1), binades 2^-14
// (below the join's edge, 1e-4) to 2^1 (up to 4 > 1/0.31 - 1 and 3.6 - 1). x's exponent and its
// first five mantissa bits are the cell, the other 47 bits the position t in it.
constexpr int first_binade = -14, binades = 16, cell_bits = 5, cells_per_binade = 1 << cell_bits;
constexpr int position_bits = 52 - cell_bits;
}  // namespace

namespace {
// Cubic Hermite on each cell, from K13 (17)'s value and slope at its two ends (per unit t),
// in (17)'s own variables: x = 1/beta - 1 below beta = 1, x = beta - 1 above.
std::vector<CrackSpeedTable::Cell> build_cells(bool above) {
  std::vector<CrackSpeedTable::Cell> cells;
  cells.reserve(binades * cells_per_binade);
  for (int e = first_binade; e < first_binade + binades; e++)
    for (int j = 0; j < cells_per_binade; j++) {
      const double x0 = std::ldexp(1.0 + double(j) / cells_per_binade, e), width = std::ldexp(1.0 / cells_per_binade, e);
      auto at = [&](double x) {  // f and df/dx times the width
        const double beta = above ? 1.0 + x : 1.0 / (1.0 + x);
        const CrackSpeed f = crack_speed_low(beta);
        return std::pair{f.value, f.derivative * (above ? 1.0 : -beta * beta) * width};
      };
      const auto [f0, s0] = at(x0);
      const auto [f1, s1] = at(x0 + width);
      cells.push_back({f0, s0, 3.0 * (f1 - f0) - 2.0 * s0 - s1, 2.0 * (f0 - f1) + s0 + s1});
    }
  return cells;
}
}  // namespace

// The cells are those of the reference law, whatever k: built once, shared by every table.
CrackSpeedTable::CrackSpeedTable(double k) : k_(k) {
  static const std::vector<Cell> below = build_cells(false), above = build_cells(true);
  below_ = &below;
  above_ = &above;
}

CrackSpeed CrackSpeedTable::lookup(const std::vector<Cell>& cells, double x) const {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const int exponent = int(bits >> 52) - 1023;
  const Cell& c = cells[std::size_t((exponent - first_binade) * cells_per_binade) +
                        std::size_t((bits >> position_bits) & (cells_per_binade - 1))];
  const double t = double(bits & ((std::uint64_t{1} << position_bits) - 1)) * std::ldexp(1.0, -position_bits);
  // d/dx = d/dt / width, width = 2^(exponent - cell_bits).
  const double per_width = std::bit_cast<double>(std::uint64_t(1023 + cell_bits - exponent) << 52);
  return {c.c0 + t * (c.c1 + t * (c.c2 + t * c.c3)), (c.c1 + t * (2.0 * c.c2 + t * 3.0 * c.c3)) * per_width};
}

CrackSpeed CrackSpeedTable::reference(double beta) const {
  if (beta >= low_band_bottom && beta <= low_band_top) {
    if (beta <= 1.0 - crack_smoothing_width) {
      const double inverse = 1.0 / beta;  // x = 1/beta - 1, dx/dbeta = -1/beta^2
      const CrackSpeed f = lookup(*below_, inverse - 1.0);
      return {f.value, -f.derivative * inverse * inverse};
    }
    if (beta >= 1.0 + crack_smoothing_width) return lookup(*above_, beta - 1.0);
  }
  return reference_law(beta);
}

CrackSpeed CrackSpeedTable::operator()(double beta) const {
  const CrackBeta r = reference_beta(beta, k_);
  return crack_speed_at_k(reference(r.beta), beta, r);
}

}  // namespace bounce::models

// The rolling, sliding and twisting resistance of a JKR contact (resistance.hpp,
// docs/resistance.md).
#include "bounce/contact/resistance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "bounce/contact/jkr.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/mixing.hpp"

namespace bounce::contact::resistance {

namespace {
constexpr double pi = std::numbers::pi;
}  // namespace

double break_energy_factor() {
  // W07 §2.2 with x = a/a0: F/F_c = 4x^3 - 4x^{3/2}, delta/delta_c = 6^{1/3} (2x^2 - (4/3) x^{1/2}); the
  // work -int F d(delta) from x = 1 to the fold x_f = 6^{-2/3} is 6^{1/3} [P(1) - P(x_f)] with the
  // antiderivative P(x) = -(16/5) x^5 + (16/3) x^{7/2} - (4/3) x^2 of -F d(delta)/dx.
  const auto p = [](double x) { return -16.0 / 5.0 * std::pow(x, 5) + 16.0 / 3.0 * std::pow(x, 3.5) - 4.0 / 3.0 * x * x; };
  const double cbrt6 = std::cbrt(6.0);
  return cbrt6 * (p(1.0) - p(1.0 / (cbrt6 * cbrt6)));
}

Materials materials_of(const Pair& pair, const std::string& who) {
  const Material& m1 = pair.body1().material;
  const Material& m2 = pair.body2().material;
  const double g1 = shear_modulus(m1.youngs_modulus, m1.poisson_ratio);
  const double g2 =
      pair.body2().rigid ? std::numeric_limits<double>::infinity() : shear_modulus(m2.youngs_modulus, m2.poisson_ratio);
  // docs/resistance.md, unlike pairs: the twisting spring takes the moduli in series (G for like
  // bodies, 2 G1 on a rigid wall), the limits the weaker body's strength.
  const double series = std::isinf(g2) ? 2.0 * g1 : 2.0 * g1 * g2 / (g1 + g2);
  return {pair.effective_modulus(), pair.require_surface_energy(who),
          effective_shear_modulus(g1, m1.poisson_ratio, g2, m2.poisson_ratio), series, std::min(g1, g2)};
}

Springs springs(const Materials& m, double radius) {
  const jkr::Parameters jp{radius, m.effective_modulus, m.surface_energy};
  Springs s;
  const double a0 = jkr::equilibrium_contact_radius(jp);  // W07: (9 pi gamma_s R^2 / E*)^{1/3}
  s.contact_radius = a0;
  s.rolling = 4.0 * -jkr::pull_off_force(jp) / radius;  // W07 §2.2: k_r = 4 F_c / R, F_c = 3 pi gamma_s R
  // W07 §2.2 sliding: k_s = 8 a0 G*; like bodies xi_s = (2 - nu) a0 / (16 pi), i.e. F_slide = G a0^2 / (4 pi).
  s.sliding = 8.0 * a0 * m.tangential_modulus;
  s.sliding_critical = m.weaker_shear * a0 * a0 / (4.0 * pi) / s.sliding;
  // W07 §2.2 twisting: k_t = (16/3) G a0^3; like bodies phi_crit = 1/(16 pi), i.e. M_twist = G a0^3 / (3 pi).
  s.twisting = 16.0 / 3.0 * m.series_shear * a0 * a0 * a0;
  s.twisting_critical = m.weaker_shear / (16.0 * pi * m.series_shear);
  return s;
}

Resistance contact_resistance(const Materials& m, double radius, double xi_crit) {
  const jkr::Parameters jp{radius, m.effective_modulus, m.surface_energy};
  const Springs k = springs(m, radius);
  Resistance r;
  r.surface_energy = 0.5 * m.surface_energy;
  r.contact_radius = k.contact_radius;
  r.pull_off_force = -jkr::pull_off_force(jp);        // W07: 3 pi gamma_s R
  r.critical_overlap = -jkr::separation_overlap(jp);  // W07: a0^2 / (2 6^{1/3} R)
  r.break_energy = break_energy_factor() * r.pull_off_force * r.critical_overlap;
  // The limits are the springs at their critical displacements (the rolling moment's lever R),
  // and each energy the limit's work over a quarter turn.
  r.rolling = {k.rolling, xi_crit, k.rolling * radius * xi_crit, 0.0};
  r.rolling.energy = 0.5 * pi * r.rolling.limit;       // DT97: E_roll = 6 pi^2 gamma_s R xi_crit
  r.rolling_force = r.rolling.limit / (2.0 * radius);  // DT95: F_roll = 6 pi gamma_s xi_crit
  const double f_slide = k.sliding * k.sliding_critical, m_twist = k.twisting * k.twisting_critical;
  r.sliding = {k.sliding, k.sliding_critical, f_slide, f_slide * 0.5 * pi * radius};
  r.twisting = {k.twisting, k.twisting_critical, m_twist, 0.5 * pi * m_twist};
  return r;
}

Resistance contact_resistance(const Pair& pair, double xi_crit) {
  const Resistance r = contact_resistance(materials_of(pair), pair.effective_radius(), xi_crit);
  if (!(xi_crit > 0.0) || !(xi_crit < r.contact_radius)) {
    throw InvalidArgument("xi_crit", format_value(xi_crit),
                          fmt::format("0 < xi_crit < a0 = {} m (the contact's radius at zero load; W07's standard "
                                      "is 8e-10 m)",
                                      format_value(r.contact_radius)));
  }
  return r;
}

}  // namespace bounce::contact::resistance

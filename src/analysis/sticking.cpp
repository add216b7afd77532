#include "bounce/analysis/sticking.hpp"

#include <cmath>

#include <boost/math/tools/roots.hpp>
#include <fmt/format.h>

#include "bisect.hpp"
#include "bounce/analytic/adhesive.hpp"
#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::analysis {

namespace {

// From a speed that sticks, up by factors of 2 until one bounces; the quasi-static models
// hold well below the transversal sound speed (BSHP96 (B11)), so the search stops there
// (false: they stick at every speed up to it).
template <class Sticks>
bool bracket_upwards(StickingVelocity& s, double v, double c_t, Sticks sticks) {
  s.lower = v;
  s.upper = std::min(2.0 * v, c_t);
  while (sticks(s.upper)) {
    if (s.upper >= c_t) return false;
    s.lower = s.upper;
    s.upper = std::min(2.0 * s.upper, c_t);
  }
  return true;
}

// From a speed that bounces, down by factors of 2 until one sticks.
template <class Sticks>
void bracket_downwards(StickingVelocity& s, double v, Sticks sticks) {
  s.upper = v;
  s.lower = 0.5 * v;
  while (!sticks(s.lower)) {
    s.upper = s.lower;
    s.lower *= 0.5;
    if (s.lower < 1e-8 * v) throw NumericalError(fmt::format("the grains still bounce at {:.3g} m/s", s.lower));
  }
}

}  // namespace

StickingVelocity sticking_velocity(const Pair& pair, const models::Model& model, const CollideOptions& options,
                                   double relative_tolerance) {
  if (!model.traits.adhesive) {
    throw InvalidArgument("model", model.name, "an adhesive model (adhesive-viscoelastic, jkr-viscoelastic, krijt)");
  }
  const double gamma = pair.require_surface_energy("the sticking velocity");
  StickingVelocity s;
  auto sticks = [&](double v) {
    ++s.collisions;
    return collide(pair, model, v, options).outcome == dynamics::Outcome::stick;
  };
  // Start from the elastic JKR threshold and bracket by factors of 2.
  const double v = analytic::sticking_velocity_jkr(pair.effective_mass(), pair.effective_radius(),
                                                   pair.effective_modulus(), gamma);
  if (!std::isnormal(v)) {
    throw NumericalError(fmt::format(
        "the elastic JKR sticking velocity (K13 (24), where the search starts) is {} m/s for gamma = {:g} J/m^2: "
        "outside double precision, so no sticking velocity can be computed for this pair",
        format_value(v), gamma));
  }
  const double c_t = pair.transversal_sound_speed();
  if (sticks(v)) {
    if (!bracket_upwards(s, v, c_t, sticks)) {
      s.sticks_up_to_sound_speed = true;
      s.lower = c_t;
      s.upper = 0.0;
      return s;
    }
  } else {
    bracket_downwards(s, v, sticks);
  }
  std::tie(s.lower, s.upper) = detail::bisect_speed(s.lower, s.upper, sticks, relative_tolerance);
  s.velocity = std::sqrt(s.lower * s.upper);
  return s;
}

double sticking_velocity_bp04(const Pair& pair, const models::Model& model) {  // BP04 (8.100)
  const double gamma = pair.require_surface_energy("BP04's sticking velocity (8.100)");
  const double w0 = analytic::tensile_work(pair.effective_radius(), pair.effective_modulus(), gamma);
  const double m = pair.effective_mass();
  const double g0 = std::sqrt(2.0 * w0 / m);
  const ViscoelasticScales scales = viscoelastic_scales(pair, model, g0);
  const double a = scales.dissipative_constant, c0 = scales.force_constant;
  // e(g) g increases with g (e falls like g^{-1/5} at most): one root above g0.
  auto f = [&](double g) {
    return analytic::master_cor(analytic::kappa(a, c0, m, g), models::EndRule::overlap) * g - g0;
  };
  if (f(g0) >= 0.0) return g0;  // no damping: e = 1, g_st = sqrt(2 W0/m)
  double hi = 2.0 * g0;
  while (f(hi) < 0.0) hi *= 2.0;
  std::uintmax_t iterations = 200;
  const auto r = boost::math::tools::toms748_solve(f, g0, hi, boost::math::tools::eps_tolerance<double>(50), iterations);
  return 0.5 * (r.first + r.second);
}

}  // namespace bounce::analysis

#include "bounce/models/krijt.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <numbers>
#include <optional>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <fmt/format.h>

#include "bounce/contact/hertz.hpp"
#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/models/dem_law.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/mixing.hpp"
#include "bounce/models/crack.hpp"
#include "factories.hpp"
#include "adhesive_dem_law.hpp"
#include "adhesive_geometries.hpp"
#include "crack_step.hpp"
#include "hertz_type.hpp"

namespace bounce::models {

namespace {
constexpr double pi = std::numbers::pi;
}

double KrijtParameters::crack_speed_scale() const {  // K13 (16): E* gamma / (sigma0^2 T_vis)
  return effective_modulus * z0 * z0 / (surface_energy * relaxation_time);
}

double krijt_dissipative_constant(double relaxation_time, const Pair& pair) {  // K13 after (18)
  const Material& m1 = pair.body1().material;
  const Material& m2 = pair.body2().material;
  double nu = m1.poisson_ratio;
  bool second = false;
  if (!pair.body2().rigid) {
    const double c1 = (1.0 - m1.poisson_ratio * m1.poisson_ratio) / m1.youngs_modulus;
    const double c2 = (1.0 - m2.poisson_ratio * m2.poisson_ratio) / m2.youngs_modulus;
    second = c2 > c1;
    if (second) nu = m2.poisson_ratio;
  }
  detail::require_short_viscous_time(pair, relaxation_time, "tvis", "a viscous relaxation time T_vis [s]");
  const double a = relaxation_time / (nu * nu);
  // nu = 0 (inside -1 < nu < 0.5) made A = inf and nu = 1e-6 A = 10 s, and the solvers failed in
  // their own words or integrated nonsense (issue 40, point 5): refused naming both inputs.
  const double longest = detail::longest_viscous_time_ratio * detail::shortest_contact_time(pair);
  if (!(a <= longest)) {
    throw InvalidArgument(second ? "nu2" : "nu", format_value(nu),
                          fmt::format("|nu| >= {:.3g} with tvis = {:g} s: A = T_vis / nu^2 (K13 after (18)) is {} and "
                                      "must stay <= {:g} t_H(c_t) = {:.3g} s like a given A (docs/models.md); or give A",
                                      std::sqrt(relaxation_time / longest), relaxation_time,
                                      std::isfinite(a) ? fmt::format("{:.3g} s", a) : "beyond double precision",
                                      detail::longest_viscous_time_ratio, longest));
  }
  return a;
}

double effective_surface_energy_ratio(const AdhesivePair& p, double a, double delta) {  // K13 (14)
  const contact::independent::Geometry g{p.effective_radius, p.effective_modulus};
  return contact::independent::effective_surface_energy(g, a, delta) / p.surface_energy;
}

double elastic_force(const AdhesivePair& p, double a, double delta) {  // K13 (2)
  return contact::independent::elastic_force({p.effective_radius, p.effective_modulus}, a, delta);
}

double bulk_dissipative_force(const AdhesivePair& p, double a, double rate) {  // K13 (19)
  return 2.0 * p.dissipative_constant * p.effective_modulus * a * rate;
}

double contact_energy(const AdhesivePair& p, double a, double delta) {  // K13 (3) + (6)
  return contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, a, delta) +
         contact::independent::surface_energy(a, p.surface_energy);
}

double krijt_hysteresis_estimate(const KrijtParameters& p, double speed) {
  const double rho = hertz_constant(p.effective_modulus, p.effective_radius);  // BP04 (8.24)
  const double xi0 = contact::hertz::reference_overlap(rho, p.effective_mass, speed);
  const double a_eq = std::cbrt(9.0 * pi * p.surface_energy * p.effective_radius * p.effective_radius /
                                (2.0 * p.effective_modulus));                         // K13 (10)
  const double a = std::max(std::sqrt(p.effective_radius * xi0), a_eq);
  const double t_c = contact::hertz::collision_time(rho, p.effective_mass, speed);
  const double phi = a / (p.crack_speed_scale() * t_c);
  const double energy = 0.5 * p.effective_mass * speed * speed;
  return 2.0 * pi * a * a * p.surface_energy / energy * std::pow(phi / 0.39, 1.0 / 1.14);
}

CrackStep krijt_crack_step(const KrijtParameters& p, double a_old, double delta, double dt) {  // K13 (14)-(17)
  return detail::implicit_crack_step(detail::CrackConstants(p), a_old, delta, dt, a_old,
                                     [&](double b) { return crack_speed_function(b, p.k); });
}

CrackStep krijt_crack_step(const KrijtParameters& p, double a_old, double delta, double dt, double a_older,
                           double ratio, double guess) {  // K13 (14)-(17) by variable-step BDF2
  return detail::bdf2_crack_step(detail::CrackConstants(p), a_old, delta, dt, a_older, ratio, guess,
                                 [&](double b) { return crack_speed_function(b, p.k); });
}

namespace {
// (B.1): at delta = 0, beta = E* a^3 / (2 pi R^2 gamma), so a = (2 pi R^2 beta gamma / E*)^{1/3}.
double radius_at_touch(const KrijtParameters& p, double beta) {
  return std::cbrt(2.0 * pi * p.effective_radius * p.effective_radius * beta * p.surface_energy / p.effective_modulus);
}
// "1.01 k beta" of K13 read as G_eff = 1.01 k gamma (docs/decisions.md D8).
double formation_ratio(const KrijtParameters& p) { return 1.01 * p.k; }
}  // namespace

double krijt_formation_radius(const KrijtParameters& p) {  // K13 (B.1)
  return radius_at_touch(p, formation_ratio(p));
}

InitialContact krijt_initial_contact(const KrijtParameters& p) {  // K13 appendix B
  auto radius = [&](double beta) { return radius_at_touch(p, beta); };
  InitialContact c;
  const double beta0 = formation_ratio(p);
  c.contact_radius = radius(beta0);
  // t = int da / a' with da = a dbeta / (3 beta) and a' = c f(beta): substitute beta = k + (beta0 - k) s^2
  // so that the integrand (which vanishes like f^-1 at beta = k) is smooth.
  const double speed = p.crack_speed_scale();
  auto integrand = [&](double s) {
    const double beta = p.k + (beta0 - p.k) * s * s;
    const double f = crack_speed_function(beta, p.k).value;
    return radius(beta) / (3.0 * beta) / (speed * f) * 2.0 * (beta0 - p.k) * s;
  };
  c.time = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, 0.0, 1.0, 10, 1e-12);
  c.crack_dissipated = -contact_energy(p, c.contact_radius, 0.0);
  return c;
}

double krijt_release_overlap(const KrijtParameters& p) {  // K13 (14) at its least over a
  const double r2 = p.effective_radius * p.effective_radius;
  const double top = (1.0 - krijt_break_margin) / p.k;
  const double d = std::pow(top * 2.0 * pi * r2 * p.surface_energy * 9.0 / (16.0 * std::sqrt(3.0) * p.effective_modulus),
                            2.0 / 3.0);
  return -d / p.effective_radius;
}

// --- the registry's factories: krijt and its fast-crack limit jkr-viscoelastic -------

namespace {

// krijt per DEM contact: K13 (2) + (19) with the contact radius a of the contact's state,
// moved each step by krijt_crack_step; the contact forms as K13 appendix B has it and ends at
// K13's run-away.
class KrijtContact final : public DemCrackLaw {
 public:
  explicit KrijtContact(const KrijtParameters& p)
      : p_(p), constants_(p), speed_(p.k) {}
  CrackState form(const ContactGeometry& g, double& dissipated) const override {  // K13 appendix B
    const KrijtParameters p = at(g);
    const double a0 = krijt_formation_radius(p);
    dissipated = -contact_energy(p, a0, 0.0);
    return {a0, 0.0, 0.0, 0.0};
  }
  CrackAdvance advance(const ContactGeometry& g, double before, double delta, double dt, CrackState& s,
                       Refinement refine) const override {
    const detail::CrackConstants p = constants_.at(g.effective_radius);
    CrackState one = s;
    const CrackAdvance whole = step(p, before, delta, dt, one);
    if (refine == Refinement::none) {
      s = one;
      return whole;
    }
    if (whole.broken && refine == Refinement::unless_broken) return whole;  // s as it was
    // Where the crack moves fast (forming, or running away at the end) one step lags behind it
    // (6 % in a at the last step before K13's run-away at t_H/100, for micrometre ice): such a
    // step is taken again as 16 steps, the overlap moving linearly between its two ends. Fast:
    // after a uniform step, BDF2's local error (2/11) |a - a_p| (Milne's device: a_p the
    // quadratic predictor, whose error is -9/2 times BDF2's) above `tolerance` a; after any
    // other step (the first after forming) a moved by more than 2 %; or the step broke the
    // contact. (A 2 % rule everywhere divided 30 % of the steps of a collision at 5 m/s, where a
    // moves 2-3 % a step smoothly; (error / tolerance)^{1/3} steps instead of 16 took the
    // largest COR error at t_H/400 from 1.2e-4 to 1.8e-4, their first step being backward
    // Euler's.)
    const auto predicted = predictor(s, dt);
    const bool fast = whole.broken ||
                      (predicted ? (2.0 / 11.0) * std::abs(one.contact_radius - *predicted) > tolerance * s.contact_radius
                                 : std::abs(one.contact_radius - s.contact_radius) > fast_change * s.contact_radius);
    if (!fast) {
      s = one;
      return whole;
    }
    CrackState sub = s;
    CrackAdvance total;
    for (int i = 0; i < substeps && !total.broken; i++) {
      const double from = before + (delta - before) * i / substeps, to = before + (delta - before) * (i + 1) / substeps;
      const CrackAdvance a = step(p, from, to, dt / substeps, sub);
      total.dissipated += a.dissipated;
      total.broken = a.broken;
    }
    // The next step's BDF2 takes this whole step as its last one.
    sub.older_radius = s.previous_step == dt ? s.previous_radius : 0.0;
    sub.previous_radius = s.contact_radius;
    sub.previous_step = dt;
    s = sub;
    return total;
  }
  Force force(const ContactGeometry& g, double delta, const CrackState& s) const override {  // K13 (2), (19)
    const double a = s.contact_radius;
    return {contact::independent::elastic_force({g.effective_radius, p_.effective_modulus}, a, delta),
            bulk_dissipative_force(p_, a, 1.0)};  // (19) does not depend on R
  }
  double elastic_energy(const ContactGeometry& g, double delta, const CrackState& s) const override {  // K13 (3)
    return contact::independent::elastic_energy({g.effective_radius, p_.effective_modulus}, s.contact_radius, delta);
  }
  double surface_energy(const ContactGeometry&, const CrackState& s) const override {  // K13 (6)
    return contact::independent::surface_energy(s.contact_radius, p_.surface_energy);
  }
  double release_overlap(const ContactGeometry& g) const override { return krijt_release_overlap(at(g)); }

 private:
  static constexpr double fast_change = 0.02;  // relative change of a in one step
  static constexpr int substeps = 16;
  static constexpr double tolerance = 1e-4;    // of BDF2's local error in a, relative

  // The quadratic through the last three radii at the end of a step dt, where the last two were
  // dt too: a_p = 3 a_n - 3 a_n-1 + a_n-2, whose error is -dt^3 times a's third derivative.
  static std::optional<double> predictor(const CrackState& s, double dt) {
    if (s.previous_step != dt || !(s.older_radius > 0.0)) return std::nullopt;
    return 3.0 * s.contact_radius - 3.0 * s.previous_radius + s.older_radius;
  }

  // One crack step: BDF2 where the step before is known and of about the same length; backward
  // Euler otherwise (the first step, or the doubling stretches of a forming contact, where BDF2
  // left a 0.6 % too large against 0.08 % for backward Euler).
  CrackAdvance step(const detail::CrackConstants& p, double before, double delta, double dt, CrackState& s) const {
    const double ratio = s.previous_step > 0.0 ? dt / s.previous_step : 0.0;
    const bool uniform = ratio > 0.9 && ratio < 1.1;
    // Newton's first guess: the quadratic predictor (its error, O(dt^3), ~1e-6 a, lets one
    // iteration land), else BDF2's line.
    const double guess = predictor(s, dt).value_or(0.0);
    const CrackStep step =
        uniform ? detail::bdf2_crack_step(p, s.contact_radius, delta, dt, s.previous_radius, ratio, guess, speed_)
                : detail::implicit_crack_step(p, s.contact_radius, delta, dt, s.contact_radius, speed_);
    const double a_old = s.contact_radius, a_new = step.broken ? 0.0 : step.contact_radius;
    s.older_radius = dt == s.previous_step ? s.previous_radius : 0.0;  // for the predictor
    s.previous_radius = a_old;
    s.previous_step = dt;
    s.contact_radius = a_new;
    // -(U(a_new) - U(a_old)), averaged over the overlaps at the step's start and end, with K13
    // (3) + (6), U = E* [a xi^2 - 2 a^3 xi / (3R) + a^5 / (5R^2)] - pi gamma a^2, in one
    // expression: U's change at fixed overlap is linear in xi and xi^2, whose averages it takes.
    const double inverse_r = 1.0 / p.radius, o3 = a_old * a_old * a_old, n3 = a_new * a_new * a_new;
    const double mean = 0.5 * (delta + before), mean_square = 0.5 * (delta * delta + before * before);
    const double released =
        p_.effective_modulus * ((a_old - a_new) * mean_square - (2.0 / 3.0) * (o3 - n3) * mean * inverse_r +
                                0.2 * (o3 * a_old * a_old - n3 * a_new * a_new) * inverse_r * inverse_r) -
        pi * p_.surface_energy * (a_old * a_old - a_new * a_new);
    return {released, step.broken};
  }

  KrijtParameters at(const ContactGeometry& g) const {
    KrijtParameters p = p_;
    p.effective_radius = g.effective_radius;
    p.effective_mass = g.effective_mass;
    return p;
  }
  KrijtParameters p_;
  detail::CrackConstants constants_;  // at p_'s R; those of a contact at its own
  CrackSpeedTable speed_;     // K13 (16)/(17) at p_.k
};

}  // namespace

Made<CrackContact> make_krijt(const Pair& pair, const CrackModelParameters& p, const Context&) {
  const KrijtParameters k = detail::krijt_parameters(pair, p);
  return detail::contact_model(k, p, CrackContact{k, std::make_shared<KrijtContact>(k)});
}

// jkr-viscoelastic for the pair, and per DEM contact JKR's branch at the contact's R_eff (a few
// constants: made at every call), which holds down to the fold delta_c or the pull-off point.
Made<AdhesiveContact> make_jkr_viscoelastic(const Pair& pair, const ContactModelParameters& p, const Context& c) {
  const AdhesivePair k = detail::adhesive_pair(pair, p, "jkr-viscoelastic");
  const auto at = [e = k.effective_modulus, gamma = k.surface_energy](double r) { return detail::JkrGeometry(r, e, gamma); };
  auto dem = detail::adhesive_branch_contact(at, k.effective_modulus, k.dissipative_constant,
                                             detail::adhesive_release(c.end_rule));
  return detail::contact_model(
      k, p, AdhesiveContact{k, jkr_geometry(k.effective_radius, k.effective_modulus, k.surface_energy), std::move(dem)});
}

}  // namespace bounce::models

#include "bounce/models/krijt.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <numbers>
#include <optional>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <fmt/format.h>

#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/models/contact_law.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/crack.hpp"
#include "factories.hpp"
#include "adhesive_contact_law.hpp"
#include "adhesive_geometries.hpp"
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
  if (!pair.body2().rigid) {
    const double c1 = (1.0 - m1.poisson_ratio * m1.poisson_ratio) / m1.youngs_modulus;
    const double c2 = (1.0 - m2.poisson_ratio * m2.poisson_ratio) / m2.youngs_modulus;
    if (c2 > c1) nu = m2.poisson_ratio;
  }
  return relaxation_time / (nu * nu);
}

double effective_surface_energy_ratio(const KrijtParameters& p, double a, double delta) {  // K13 (14)
  const contact::independent::Geometry g{p.effective_radius, p.effective_modulus};
  return contact::independent::effective_surface_energy(g, a, delta) / p.surface_energy;
}

double elastic_force(const KrijtParameters& p, double a, double delta) {  // K13 (2)
  return contact::independent::elastic_force({p.effective_radius, p.effective_modulus}, a, delta);
}

double bulk_dissipative_force(const KrijtParameters& p, double a, double rate) {  // K13 (19)
  return 2.0 * p.dissipative_constant * p.effective_modulus * a * rate;
}

double contact_energy(const KrijtParameters& p, double a, double delta) {  // K13 (3) + (6)
  return contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, a, delta) +
         contact::independent::surface_energy(a, p.surface_energy);
}

double krijt_hysteresis_estimate(const KrijtParameters& p, double speed) {
  const double rho = 4.0 / 3.0 * p.effective_modulus * std::sqrt(p.effective_radius);  // BP04 (8.24)
  const double xi0 = std::pow(1.25 * p.effective_mass * speed * speed / rho, 0.4);    // BP04 (8.65)
  const double a_eq = std::cbrt(9.0 * pi * p.surface_energy * p.effective_radius * p.effective_radius /
                                (2.0 * p.effective_modulus));                         // K13 (10)
  const double a = std::max(std::sqrt(p.effective_radius * xi0), a_eq);
  const double t_c = 2.943275184 * std::pow(1.25 * p.effective_mass / rho, 0.4) * std::pow(speed, -0.2);
  const double phi = a / (p.crack_speed_scale() * t_c);
  const double energy = 0.5 * p.effective_mass * speed * speed;
  return 2.0 * pi * a * a * p.surface_energy / energy * std::pow(phi / 0.39, 1.0 / 1.14);
}

namespace {

// What a crack step needs of K13 (14)-(16) at one contact (a DEM law keeps the parts that do not
// depend on R, so that a step divides no more than it must).
struct CrackConstants {
  double radius = 0.0;         // R
  double scale_over_r2 = 0.0;  // 2 pi gamma / E*
  double scale = 0.0;          // 2 pi R^2 gamma / E*: beta = (a^2 - delta R)^2 / (scale a), K13 (14)
  double speed = 0.0;          // c of K13 (16)
  double k = 0.0;

  explicit CrackConstants(const KrijtParameters& p)
      : scale_over_r2(2.0 * pi * p.surface_energy / p.effective_modulus), speed(p.crack_speed_scale()), k(p.k) {
    *this = at(p.effective_radius);
  }
  // The same at another R, without a division.
  CrackConstants at(double r) const {
    CrackConstants c = *this;
    c.radius = r;
    c.scale = scale_over_r2 * r * r;
    return c;
  }
};

// The implicit crack step a - base = h c f(beta(a, delta)) (backward Euler: base = a_old, h = dt;
// BDF2: base = (4 a_old - a_older) / 3, h = 2 dt / 3), taking the root connected to a_old; f is
// speed(beta), crack_speed_function or the DEM's CrackSpeedTable.
template <class Speed>
CrackStep implicit_crack_step(const CrackConstants& p, double a_old, double base, double delta, double h,
                              double guess, const Speed& speed) {
  const double c = p.speed, top = (1.0 - krijt_break_margin) / p.k, bottom = p.k * (1.0 + 1e-12);
  const double scale = p.scale, delta_r = delta * p.radius;
  // K13 (14) squares a^2 - delta R, the stress intensity at the contact's edge; where it is
  // negative (a^2 < delta R: a contact smaller than Hertz's at this overlap, as a DEM's first step
  // can make it) the edge is compressed and closes as fast as the crack law allows (beta -> k),
  // not at the run-away that beta's square would mean.
  auto beta = [&](double a) {
    const double w = a * a - delta_r;
    return w <= 0.0 ? 0.0 : w * w / (scale * a);
  };
  auto residual = [&](double a) {
    return a - base - h * c * speed(std::clamp(beta(a), bottom, top)).value;
  };
  // Newton from `guess` (a_old extrapolated): a DEM step moves a by a few per cent, and one or
  // two iterations land on the root. It is taken where the residual increases at every iterate
  // (beta and f' of opposite signs) and beta stays inside (k, 1/k); from a_old, when the root
  // lies on the side of a_old the residual's sign there points to (the connected root, as the
  // search below finds it), and from another guess when it is within 25 % of a_old. It stops at
  // a step below 1e-4 a (Newton's next error, ~(1e-4)^2 a where the root is simple): from the
  // quadratic predictor that is mostly the first iterate, one crack-law evaluation a step, and
  // against stopping at 1e-9 a it moves the COR of a DEM collision by < 1e-7 (measured at
  // T_vis = 1e-14, 1e-12, 1e-11 s; its error is ~1e-4).
  // A neck that runs away is on the other branch, delta < 0 and a^2 < -delta R / 3, where beta
  // rises as a falls: the residual's slope is below 1 there. Where f is concave in beta
  // (crack_speed_concave: f' < 0, f'' <= 0) the residual a - base - h c f(beta(a)) is convex in a
  // on both branches, since beta is (beta'' = (6a + 2 (delta R)^2 / a^3) / scale > 0): Newton
  // from a_old, where the residual and its slope are positive, then descends to the connected
  // root without passing it. Such iterates are taken from a_old while beta, at every iterate and
  // at the branches' meeting point a^2 = -delta R / 3 where a step passes it (beta's least
  // value), stays where f is concave. Where Newton from the guess fails (it meets that branch,
  // say) Newton from a_old is tried; where that fails too, and where the neck breaks in the step
  // (no root), the search below decides.
  const double hc = h * c;
  const double meeting = delta_r < 0.0 ? std::sqrt(-delta_r / 3.0) : 0.0;  // the branches' meeting point
  auto concave = [&](double b) { return crack_speed_concave(b, p.k); };
  auto newton = [&](bool from_old) -> std::optional<double> {
    // beta = w^2 / (scale a), w = a^2 - delta R (K13 (14)); d beta / da = (4 a^2 w - w^2) / (scale a^2).
    double a = from_old ? a_old : guess, residual_old = 0.0;
    bool descending = from_old;  // from a_old, every iterate so far with positive residual and f concave
    for (int i = 0; i < 16; i++) {
      const double w = a * a - delta_r, w_over_a = w / (scale * a);
      const double b = w * w_over_a;
      if (!(w > 0.0 && b > bottom && b * p.k < 1.0 - krijt_break_margin)) return std::nullopt;  // b < top
      const double db = 4.0 * a * w_over_a - w_over_a * w_over_a * scale;
      const CrackSpeed f = speed(b);
      const double slope = 1.0 - hc * f.derivative * db, r = a - base - hc * f.value;
      descending = descending && r > 0.0 && concave(b);
      if (!(slope >= 1.0) && !(descending && slope > 0.0)) return std::nullopt;
      const double step = r / slope;
      if (i == 0) residual_old = r;
      if (descending && a > meeting && a - step <= meeting && !concave(beta(meeting))) return std::nullopt;
      a -= step;
      if (!(a > 0.0)) return std::nullopt;
      if (std::abs(step) <= 1e-4 * a) {
        const bool connected = from_old ? (residual_old <= 0.0) == (a >= a_old) : std::abs(a - a_old) <= 0.25 * a_old;
        return connected ? std::optional<double>(a) : std::nullopt;
      }
    }
    return std::nullopt;
  };
  const bool from_guess = guess > 0.0 && guess != a_old && std::abs(guess - a_old) < 0.1 * a_old;
  if (const auto root = from_guess ? newton(false) : std::nullopt) return {*root, false};
  if (const auto root = newton(true)) return {*root, false};

  const auto tolerance = boost::math::tools::eps_tolerance<double>(50);
  const auto bracket = [&](const auto& fn, double lo, double hi) {  // a root of fn bracketed by [lo, hi], narrowed
    std::uintmax_t limit = 200;
    return boost::math::tools::toms748_solve(fn, lo, hi, tolerance, limit);
  };
  const auto solve = [&](double lo, double hi) {  // a root of the residual bracketed by [lo, hi]
    const auto [x0, x1] = bracket(residual, lo, hi);
    return CrackStep{0.5 * (x0 + x1), false};
  };
  if (residual(a_old) <= 0.0) {  // the contact grows: the residual increases above a_old
    double hi = 2.0 * a_old;
    while (residual(hi) <= 0.0) hi *= 2.0;
    return solve(a_old, hi);
  }
  // It shrinks: the root is the largest a below a_old where the residual is <= 0, with beta < 1/k
  // on the way (where beta >= 1/k the crack would open at a speed without bound; K13's run-away
  // is beta >= 1/k rising as a falls, where nothing below can hold the neck). f never increases
  // with beta (tested on a dense grid for k from 1e-9 to 0.99: CrackLaw.NeverIncreasesWithBeta),
  // so on the branch where beta rises with a (a > the meeting point; every a > 0 where delta >= 0)
  // the residual rises with a: one root at most there, found from a sign change.
  auto over_top = [&](double a) { return beta(a) - top; };
  if (delta_r < 0.0 && over_top(meeting) >= 0.0) return {0.0, true};  // beta >= 1/k at its least
  if (a_old > meeting && residual(meeting) <= 0.0) {
    // A root where beta >= 1/k is none: the crack runs at a speed without bound there (the
    // residual's f is clamped at (1 - 1e-6)/k), so the neck shrinks to where beta = 1/k, or below.
    double upper = a_old;
    if (over_top(a_old) >= 0.0) {
      upper = bracket(over_top, meeting, a_old).first;  // beta < top
      if (residual(upper) <= 0.0) return {upper, false};
    }
    return solve(meeting, upper);
  }
  if (!(delta_r < 0.0)) return {0.0, true};  // r(0) = -base - h c f(~k) < 0 (f -> +inf at k): not met
  // Below the meeting point beta rises as a falls, to 1/k at a_break, and the residual can dip
  // below zero and come back (beta's rise against a's fall). But it falls no faster than a:
  // r(a - d) >= r(a) - d, since its term -h c f(beta(a)) only grows as a falls (beta rises, f
  // never increases). So no root lies within r(a) below a point a. The walk down from a_top
  // steps by r(a) where that is at least 1/32 of [a_break, a_top], and by that 1/32 otherwise,
  // solving for a sign change where one appears. The first root from the top is the connected
  // one; with none the neck breaks (K13's run-away). A dip narrower than the 1/32 that falls
  // between two of the walk's points is not seen: none was in 8163 states of a test grid and
  // 94 896 of a denser one, against scans in steps of 1e-4 a_old and 1e-5 a_old.
  const double a_top = std::min(a_old, meeting);
  if (over_top(a_top) >= 0.0) return {0.0, true};
  double a_low = 0.5 * a_top;
  while (over_top(a_low) < 0.0) a_low *= 0.5;  // beta ~ (delta R)^2 / (scale a) as a -> 0
  // The least a with beta < 1/k (the bracket's upper end).
  const double a_break = bracket(over_top, a_low, a_top).second;
  // (At least a few ulps, so that every pass moves a.)
  const double spacing = std::max((a_top - a_break) / 32.0, 4.0 * std::numeric_limits<double>::epsilon() * a_top);
  double a = a_top, r = residual(a_top);  // r > 0 at a_top (a_old, or the meeting point)
  while (a - r > a_break) {
    if (r >= spacing) {
      a -= r;  // r(a) >= 0 there: zero, a root, or positive
      r = residual(a);
      if (r <= 0.0) return {a, false};
      continue;
    }
    const double next = std::max(a - spacing, a_break), r_next = residual(next);
    if (r_next <= 0.0) return solve(next, a);  // two roots within one 1/32: the one toms748 meets
    a = next;
    r = r_next;
  }
  return {0.0, true};
}

// BDF2 with variable steps: the base and the step h of implicit_crack_step.
template <class Speed>
CrackStep bdf2_crack_step(const CrackConstants& p, double a_old, double delta, double dt, double a_older, double ratio,
                          double guess, const Speed& speed) {
  const double w = ratio, inverse_d = 1.0 / (1.0 + 2.0 * w);
  const double base = ((1.0 + w) * (1.0 + w) * a_old - w * w * a_older) * inverse_d;
  return implicit_crack_step(p, a_old, base, delta, (1.0 + w) * inverse_d * dt,
                             guess > 0.0 ? guess : a_old + w * (a_old - a_older), speed);
}

}  // namespace

CrackStep krijt_crack_step(const KrijtParameters& p, double a_old, double delta, double dt) {  // K13 (14)-(17)
  return implicit_crack_step(CrackConstants(p), a_old, a_old, delta, dt, a_old,
                             [&](double b) { return crack_speed_function(b, p.k); });
}

CrackStep krijt_crack_step(const KrijtParameters& p, double a_old, double delta, double dt, double a_older,
                           double ratio, double guess) {  // K13 (14)-(17) by variable-step BDF2
  return bdf2_crack_step(CrackConstants(p), a_old, delta, dt, a_older, ratio, guess,
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
class KrijtContact final : public CrackContactLaw {
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
    const CrackConstants p = constants_.at(g.effective_radius);
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
  CrackAdvance step(const CrackConstants& p, double before, double delta, double dt, CrackState& s) const {
    const double ratio = s.previous_step > 0.0 ? dt / s.previous_step : 0.0;
    const bool uniform = ratio > 0.9 && ratio < 1.1;
    // Newton's first guess: the quadratic predictor (its error, O(dt^3), ~1e-6 a, lets one
    // iteration land), else BDF2's line.
    const double guess = predictor(s, dt).value_or(0.0);
    const CrackStep step =
        uniform ? bdf2_crack_step(p, s.contact_radius, delta, dt, s.previous_radius, ratio, guess, speed_)
                : implicit_crack_step(p, s.contact_radius, s.contact_radius, delta, dt, s.contact_radius, speed_);
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
  CrackConstants constants_;  // at p_'s R; those of a contact at its own
  CrackSpeedTable speed_;     // K13 (16)/(17) at p_.k
};

}  // namespace

std::shared_ptr<const CrackContactLaw> krijt_crack_law(const Pair& pair, const Parameters& p) {
  return std::make_shared<KrijtContact>(detail::contact_parameters(pair, p, "krijt", true));
}

Model make_krijt(const Pair& pair, const Parameters& p) {
  const KrijtParameters k = detail::contact_parameters(pair, p, "krijt", true);
  return detail::contact_model(k, p, CrackContact{k});
}

// jkr-viscoelastic per DEM contact: JKR's branch at the contact's R_eff (a few constants: made at
// every call), which holds down to the fold delta_c or the pull-off point.
std::shared_ptr<const ContactLaw> jkr_viscoelastic_contact(const Pair& pair, const Parameters& p) {
  const KrijtParameters k = detail::contact_parameters(pair, p, "jkr-viscoelastic", false);
  const auto at = [e = k.effective_modulus, gamma = k.surface_energy](double r) { return detail::JkrGeometry(r, e, gamma); };
  return detail::adhesive_branch_contact(at, k.effective_modulus, k.dissipative_constant, detail::adhesive_release(p));
}

Model make_jkr_viscoelastic(const Pair& pair, const Parameters& p) {
  const KrijtParameters k = detail::contact_parameters(pair, p, "jkr-viscoelastic", false);
  return detail::contact_model(k, p, AdhesiveContact{k, jkr_geometry(k.effective_radius, k.effective_modulus, k.surface_energy)});
}

}  // namespace bounce::models

#pragma once
// Private: K13's crack over one time step, a - base = h c f(beta(a, delta)) (K13 (14)-(17)),
// solved implicitly for the root connected to a_old: backward Euler (base = a_old, h = dt) or
// variable-step BDF2. The engine's fixed-step checks (krijt_crack_step) and the DEM law
// (KrijtContact) both take their steps here; f is crack_speed_function or the DEM's
// CrackSpeedTable.
//
// A safeguarded scalar solve: Newton where it provably descends to the connected root, else a
// bracketing search that never misses it (ImplicitCrackStep below states each invariant). Its
// tolerances are in CrackStepTolerances.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include <boost/math/tools/roots.hpp>

#include "bounce/models/crack.hpp"
#include "bounce/models/krijt.hpp"

namespace bounce::models::detail {

// What a crack step needs of K13 (14)-(16) at one contact (a DEM law keeps the parts that do not
// depend on R, so that a step divides no more than it must).
struct CrackConstants {
  double radius = 0.0;         // R
  double scale_over_r2 = 0.0;  // 2 pi gamma / E*
  double scale = 0.0;          // 2 pi R^2 gamma / E*: beta = (a^2 - delta R)^2 / (scale a), K13 (14)
  double speed = 0.0;          // c of K13 (16)
  double k = 0.0;

  explicit CrackConstants(const KrijtParameters& p)
      : scale_over_r2(2.0 * std::numbers::pi * p.surface_energy / p.effective_modulus), speed(p.crack_speed_scale()),
        k(p.k) {
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

/// The solve's settings.
struct CrackStepTolerances {
  /// Newton stops at a step below this fraction of a (Newton's next error, ~(1e-4)^2 a where the
  /// root is simple): from the quadratic predictor mostly the first iterate, one crack-law
  /// evaluation a step; against 1e-9 it moves a DEM collision's COR by < 1e-7 (measured at
  /// T_vis = 1e-14, 1e-12, 1e-11 s; its error is ~1e-4).
  double newton_step = 1e-4;
  int newton_iterations = 16;
  /// A root Newton finds from a guess other than a_old is the connected one within this
  /// fraction of a_old.
  double guess_window = 0.25;
  /// A guess is tried only within this fraction of a_old.
  double guess_reach = 0.1;
  /// TOMS 748's bits and iterations.
  int bracket_bits = 50;
  std::uintmax_t bracket_iterations = 200;
  /// The walk below the branches' meeting point steps at least 1/cells of its interval.
  double walk_cells = 32.0;
};

// beta = w^2 / (scale a), w = a^2 - delta R (K13 (14)). Where w < 0 (a^2 < delta R: a contact
// smaller than Hertz's at this overlap, as a DEM's first step can make it) the edge is compressed
// and closes as fast as the crack law allows (beta -> k), not at the run-away that beta's square
// would mean (docs/decisions.md D22).
template <class Speed>
class ImplicitCrackStep {
 public:
  ImplicitCrackStep(const CrackConstants& p, double a_old, double base, double delta, double h, const Speed& speed,
                    const CrackStepTolerances& t = {})
      : p_(p), t_(t), speed_(speed), a_old_(a_old), base_(base), delta_r_(delta * p.radius), hc_(h * p.speed),
        top_((1.0 - krijt_break_margin) / p.k), bottom_(p.k * (1.0 + 1e-12)),
        meeting_(delta_r_ < 0.0 ? std::sqrt(-delta_r_ / 3.0) : 0.0) {}

  /// The step from a Newton guess (0: none).
  CrackStep solve(double guess) const {
    const bool from_guess = guess > 0.0 && guess != a_old_ && std::abs(guess - a_old_) < t_.guess_reach * a_old_;
    if (const auto root = from_guess ? newton(guess, false) : std::nullopt) return {*root, false};
    if (const auto root = newton(a_old_, true)) return {*root, false};
    if (residual(a_old_) <= 0.0) return grow();
    return shrink();
  }

 private:
  double beta(double a) const {
    const double w = a * a - delta_r_;
    return w <= 0.0 ? 0.0 : w * w / (p_.scale * a);
  }
  double residual(double a) const { return a - base_ - hc_ * speed_(std::clamp(beta(a), bottom_, top_)).value; }
  double over_top(double a) const { return beta(a) - top_; }
  bool concave(double b) const { return crack_speed_concave(b, p_.k); }

  template <class F>
  std::pair<double, double> bracket(const F& fn, double lo, double hi) const {  // a root of fn in [lo, hi], narrowed
    std::uintmax_t limit = t_.bracket_iterations;
    return boost::math::tools::toms748_solve(fn, lo, hi, boost::math::tools::eps_tolerance<double>(t_.bracket_bits),
                                             limit);
  }
  CrackStep root_in(double lo, double hi) const {  // the residual's root bracketed by [lo, hi]
    const auto [x0, x1] = bracket([this](double a) { return residual(a); }, lo, hi);
    return {0.5 * (x0 + x1), false};
  }

  // Newton from `start`: a DEM step moves a by a few per cent, and one or two iterations land on
  // the root. It is taken where the residual increases at every iterate (beta and f' of opposite
  // signs) and beta stays inside (k, 1/k); from a_old, when the root lies on the side of a_old the
  // residual's sign there points to (the connected root, as the search below finds it), and from
  // another guess when it is within guess_window of a_old.
  // A neck that runs away is on the other branch, delta < 0 and a^2 < -delta R / 3, where beta
  // rises as a falls: the residual's slope is below 1 there. Where f is concave in beta
  // (crack_speed_concave: f' < 0, f'' <= 0) the residual a - base - h c f(beta(a)) is convex in a
  // on both branches, since beta is (beta'' = (6a + 2 (delta R)^2 / a^3) / scale > 0): Newton
  // from a_old, where the residual and its slope are positive, then descends to the connected
  // root without passing it. Such iterates are taken from a_old while beta, at every iterate and
  // at the branches' meeting point a^2 = -delta R / 3 where a step passes it (beta's least
  // value), stays where f is concave.
  std::optional<double> newton(double start, bool from_old) const {
    double a = start, residual_old = 0.0;
    bool descending = from_old;  // from a_old, every iterate so far with positive residual and f concave
    for (int i = 0; i < t_.newton_iterations; i++) {
      // d beta / da = (4 a^2 w - w^2) / (scale a^2)
      const double w = a * a - delta_r_, w_over_a = w / (p_.scale * a);
      const double b = w * w_over_a;
      if (!(w > 0.0 && b > bottom_ && b * p_.k < 1.0 - krijt_break_margin)) return std::nullopt;  // b < top
      const double db = 4.0 * a * w_over_a - w_over_a * w_over_a * p_.scale;
      const CrackSpeed f = speed_(b);
      const double slope = 1.0 - hc_ * f.derivative * db, r = a - base_ - hc_ * f.value;
      descending = descending && r > 0.0 && concave(b);
      if (!(slope >= 1.0) && !(descending && slope > 0.0)) return std::nullopt;
      const double step = r / slope;
      if (i == 0) residual_old = r;
      if (descending && a > meeting_ && a - step <= meeting_ && !concave(beta(meeting_))) return std::nullopt;
      a -= step;
      if (!(a > 0.0)) return std::nullopt;
      if (std::abs(step) <= t_.newton_step * a) {
        const bool connected =
            from_old ? (residual_old <= 0.0) == (a >= a_old_) : std::abs(a - a_old_) <= t_.guess_window * a_old_;
        return connected ? std::optional<double>(a) : std::nullopt;
      }
    }
    return std::nullopt;
  }

  // The contact grows: the residual increases above a_old (f never increases with beta).
  CrackStep grow() const {
    double hi = 2.0 * a_old_;
    while (residual(hi) <= 0.0) hi *= 2.0;
    return root_in(a_old_, hi);
  }

  // It shrinks: the root is the largest a below a_old where the residual is <= 0, with beta < 1/k
  // on the way (where beta >= 1/k the crack would open at a speed without bound; K13's run-away
  // is beta >= 1/k rising as a falls, where nothing below can hold the neck). f never increases
  // with beta (tested on a dense grid for k from 1e-9 to 0.99: CrackLaw.NeverIncreasesWithBeta),
  // so on the branch where beta rises with a (a > the meeting point; every a > 0 where delta >= 0)
  // the residual rises with a: one root at most there, found from a sign change.
  CrackStep shrink() const {
    if (delta_r_ < 0.0 && over_top(meeting_) >= 0.0) return {0.0, true};  // beta >= 1/k at its least
    if (a_old_ > meeting_ && residual(meeting_) <= 0.0) {
      // A root where beta >= 1/k is none: the crack runs at a speed without bound there (the
      // residual's f is clamped at (1 - 1e-6)/k), so the neck shrinks to where beta = 1/k, or below.
      double upper = a_old_;
      if (over_top(a_old_) >= 0.0) {
        upper = bracket([this](double a) { return over_top(a); }, meeting_, a_old_).first;  // beta < top
        if (residual(upper) <= 0.0) return {upper, false};
      }
      return root_in(meeting_, upper);
    }
    if (!(delta_r_ < 0.0)) return {0.0, true};  // r(0) = -base - h c f(~k) < 0 (f -> +inf at k): not met
    return walk_below_meeting();
  }

  // Below the meeting point beta rises as a falls, to 1/k at a_break, and the residual can dip
  // below zero and come back (beta's rise against a's fall). But it falls no faster than a:
  // r(a - d) >= r(a) - d, since its term -h c f(beta(a)) only grows as a falls (beta rises, f
  // never increases). So no root lies within r(a) below a point a. The walk down from a_top
  // steps by r(a) where that is at least 1/32 of [a_break, a_top], and by that 1/32 otherwise,
  // solving for a sign change where one appears. The first root from the top is the connected
  // one; with none the neck breaks (K13's run-away). A dip narrower than the 1/32 that falls
  // between two of the walk's points is not seen: none was in 8163 states of a test grid and
  // 94 896 of a denser one, against scans in steps of 1e-4 a_old and 1e-5 a_old.
  CrackStep walk_below_meeting() const {
    const double a_top = std::min(a_old_, meeting_);
    if (over_top(a_top) >= 0.0) return {0.0, true};
    double a_low = 0.5 * a_top;
    while (over_top(a_low) < 0.0) a_low *= 0.5;  // beta ~ (delta R)^2 / (scale a) as a -> 0
    // The least a with beta < 1/k (the bracket's upper end).
    const double a_break = bracket([this](double a) { return over_top(a); }, a_low, a_top).second;
    // (At least a few ulps, so that every pass moves a.)
    const double spacing =
        std::max((a_top - a_break) / t_.walk_cells, 4.0 * std::numeric_limits<double>::epsilon() * a_top);
    double a = a_top, r = residual(a_top);  // r > 0 at a_top (a_old, or the meeting point)
    while (a - r > a_break) {
      if (r >= spacing) {
        a -= r;  // r(a) >= 0 there: zero, a root, or positive
        r = residual(a);
        if (r <= 0.0) return {a, false};
        continue;
      }
      const double next = std::max(a - spacing, a_break), r_next = residual(next);
      if (r_next <= 0.0) return root_in(next, a);  // two roots within one cell: the one toms748 meets
      a = next;
      r = r_next;
    }
    return {0.0, true};
  }

  const CrackConstants& p_;
  const CrackStepTolerances t_;
  const Speed& speed_;
  const double a_old_, base_, delta_r_, hc_, top_, bottom_;
  const double meeting_;  // the branches' meeting point a^2 = -delta R / 3 (0 where delta >= 0)
};

/// Backward Euler: a - a_old = dt c f(beta(a, delta)), Newton from `guess`.
template <class Speed>
CrackStep implicit_crack_step(const CrackConstants& p, double a_old, double delta, double dt, double guess,
                              const Speed& speed) {
  return ImplicitCrackStep<Speed>(p, a_old, a_old, delta, dt, speed).solve(guess);
}

/// BDF2 with variable steps (ratio = dt / the step before, a_older the radius before a_old).
template <class Speed>
CrackStep bdf2_crack_step(const CrackConstants& p, double a_old, double delta, double dt, double a_older, double ratio,
                          double guess, const Speed& speed) {
  const double w = ratio, inverse_d = 1.0 / (1.0 + 2.0 * w);
  const double base = ((1.0 + w) * (1.0 + w) * a_old - w * w * a_older) * inverse_d;
  return ImplicitCrackStep<Speed>(p, a_old, base, delta, (1.0 + w) * inverse_d * dt, speed)
      .solve(guess > 0.0 ? guess : a_old + w * (a_old - a_older));
}

}  // namespace bounce::models::detail

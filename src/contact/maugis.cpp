#include "bounce/contact/maugis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <fmt/format.h>

#include "bounce/contact/law.hpp"
#include "bounce/contact/surface_forces.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::contact::maugis {

namespace {

constexpr double pi = std::numbers::pi;

// (s^2 - 1) atan s + s, computed without cancellation for small s.
double first_bracket(double s) {
  if (s < 1e-2) {
    const double s2 = s * s;
    // s - atan s = s^3/3 - s^5/5 + s^7/7 - s^9/9 + O(s^11)
    const double s_minus_atan = s * s2 * (1.0 / 3.0 - s2 * (0.2 - s2 * (1.0 / 7.0 - s2 / 9.0)));
    return s2 * std::atan(s) + s_minus_atan;
  }
  return (s * s - 1.0) * std::atan(s) + s;
}

// s atan s - (sqrt(1 + s^2) - 1) = sqrt(m^2-1) arcsec m - m + 1.
double second_bracket(double s) {
  return s * std::atan(s) - s * s / (1.0 + std::sqrt(1.0 + s * s));
}

// Residual of (MD1) at zone parameter s for contact radius A.
double md1(double lambda, double A, double s) {
  return 0.5 * lambda * A * A * first_bracket(s) +
         4.0 / 3.0 * lambda * lambda * A * second_bracket(s) - 1.0;
}

double solve_s(double lambda, double A) {
  // md1 increases monotonically from -1 at s = 0 (d/ds of both brackets > 0).
  double hi = 1.0;
  while (md1(lambda, A, hi) < 0.0) {
    hi *= 2.0;
    if (hi > 1e300) throw NumericalError("Maugis-Dugdale: zone size not bracketed");
  }
  std::uintmax_t iterations = 300;
  auto [lo_s, hi_s] = boost::math::tools::toms748_solve(
      [&](double s) { return md1(lambda, A, s); }, 0.0, hi, -1.0, md1(lambda, A, hi),
      boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (lo_s + hi_s);
}

void check_lambda(double lambda) {
  require_positive("lambda", lambda, "Maugis parameter lambda");
}

// Largest A in [A_lo, inf) where value(A) = target, with value increasing there.
template <class F>
double largest_root(F value, double target, double a_lo) {
  double hi = std::max(2.0 * a_lo, 1.0);
  while (value(hi) < target) {
    hi *= 2.0;
    // P ~ A^3 and Delta ~ A^2: past A = 1e60 the state is beyond double precision.
    if (hi > 1e60) throw NumericalError("Maugis-Dugdale: the state is beyond double precision (force or overlap too large)");
  }
  if (value(a_lo) >= target) return a_lo;
  std::uintmax_t iterations = 300;
  try {
    auto [x0, x1] = boost::math::tools::toms748_solve(
        [&](double A) { return value(A) - target; }, a_lo, hi,
        boost::math::tools::eps_tolerance<double>(50), iterations);
    return 0.5 * (x0 + x1);
  } catch (const std::domain_error& e) {  // Boost's "do not bracket": reported as bounce's own error
    throw NumericalError(fmt::format("Maugis-Dugdale: no contact radius found ({})", e.what()));
  }
}

// Global minimum of value(A) over A >= 0: scan, then refine with Brent.
template <class F>
double argmin(F value) {
  // The minimum lies below A = 3 for every lambda (JKR: 4^{-1/3}·(3/2)^{... } ~ 0.63,
  // DMT: A = 0); scan a log grid that also covers A = 0 exactly.
  double best_a = 0.0;
  double best_v = value(0.0);
  double previous = 0.0;
  double lower = 0.0, upper = 1e-8;
  for (int i = 0; i <= 400; ++i) {
    const double A = 1e-8 * std::pow(10.0, i * (8.5 / 400.0));  // 1e-8 … ~3
    const double v = value(A);
    if (v < best_v) {
      best_v = v;
      best_a = A;
      lower = previous;
      upper = 1e-8 * std::pow(10.0, (i + 1) * (8.5 / 400.0));
    }
    previous = A;
  }
  if (best_a == 0.0) return 0.0;
  std::uintmax_t iterations = 200;
  // Brent's precision is limited to half the mantissa (26 bits for double).
  auto [a, v] = boost::math::tools::brent_find_minima(
      value, lower, upper, std::numeric_limits<double>::digits / 2, iterations);
  (void)v;
  return a;
}

}  // namespace

Point at_contact_radius(double lambda, double A) {
  check_lambda(lambda);
  require_non_negative("contact_radius", A, "non-dimensional contact radius");
  Point p;
  p.contact_radius = A;
  if (A == 0.0) {
    // As A -> 0, s ~ c/A with c the finite zone radius: (MD1) becomes
    // (lambda/2)(pi/2) c^2 + (4/3) lambda^2 (pi/2 - 1) c = 1, and
    // P -> -lambda (pi/2) c^2, Delta -> -(4/3) lambda c.
    const double qa = 0.25 * pi * lambda;
    const double qb = 4.0 / 3.0 * lambda * lambda * (0.5 * pi - 1.0);
    const double c = 2.0 / (qb + std::sqrt(qb * qb + 4.0 * qa));  // root of qa c^2 + qb c - 1
    p.force = -lambda * 0.5 * pi * c * c;
    p.overlap = -4.0 / 3.0 * lambda * c;
    p.zone_ratio = std::numeric_limits<double>::infinity();
    return p;
  }
  const double s = solve_s(lambda, A);
  const double atan_s = std::atan(s);
  p.zone_ratio = std::sqrt(1.0 + s * s);
  p.force = A * A * A - lambda * A * A * (s + (1.0 + s * s) * atan_s);  // (MD2)
  p.overlap = A * A - 4.0 / 3.0 * lambda * A * s;                      // (MD3)
  return p;
}

Curve::Curve(double lambda) : lambda_(lambda) {
  check_lambda(lambda);
  pull_off_ = at_contact_radius(argmin([&](double a) { return maugis::at_contact_radius(lambda, a).force; }));
  min_overlap_ =
      at_contact_radius(argmin([&](double a) { return maugis::at_contact_radius(lambda, a).overlap; }));
}

Point Curve::at_contact_radius(double contact_radius) const {
  return maugis::at_contact_radius(lambda_, contact_radius);
}

Point Curve::at_force(double force) const {
  if (!(force >= pull_off_.force)) {
    throw InvalidArgument("force", format_value(force),
                          "a non-dimensional force >= the pull-off force " +
                              format_value(pull_off_.force));
  }
  return at_contact_radius(largest_root([&](double a) { return at_contact_radius(a).force; }, force,
                                        pull_off_.contact_radius));
}

Point Curve::at_overlap(double overlap) const {
  if (!(overlap >= min_overlap_.overlap)) {
    throw InvalidArgument("overlap", format_value(overlap),
                          "a non-dimensional overlap >= " + format_value(min_overlap_.overlap));
  }
  return at_contact_radius(largest_root([&](double a) { return at_contact_radius(a).overlap; },
                                        overlap, min_overlap_.contact_radius));
}

Point pull_off(double lambda) { return Curve(lambda).pull_off(); }
Point min_overlap(double lambda) { return Curve(lambda).min_overlap(); }
Point at_force(double lambda, double force) { return Curve(lambda).at_force(force); }
Point at_overlap(double lambda, double overlap) { return Curve(lambda).at_overlap(overlap); }

Scales scales(double R, double e_star, double gamma) {
  const double k = 4.0 * e_star / 3.0;
  Scales s;
  s.length = std::cbrt(pi * gamma * R * R / k);
  s.force = pi * gamma * R;
  s.overlap = s.length * s.length / R;
  return s;
}

}  // namespace bounce::contact::maugis

// --- the "maugis" contact law ----------------------------------------------------

namespace bounce::contact {
namespace {

constexpr double jkr_limit_lambda = 1e8;

class MaugisLaw final : public ContactLaw {
 public:
  MaugisLaw(const Pair& pair, double z0) {
    const double gamma = pair.require_surface_energy("law maugis");
    require_positive("gamma", gamma, "surface energy gamma [J/m^2] (maugis needs gamma > 0)");
    // Past lambda = 1e8 the Maugis-Dugdale curve is JKR's to double precision (the
    // difference falls as lambda^-2: 3e-11 in the pull-off force at lambda = 2e5, none at
    // 2e7), while (MD1)'s brackets lose every digit by lambda ~ 1e40 (z0 ~ 1e-100 m gave a
    // pull-off of -3e47 N): the curve is computed at min(lambda, 1e8), the JKR limit.
    const double lambda = surface::maugis_parameter(pair.effective_radius(), pair.effective_modulus(), gamma, z0);
    curve_.emplace(std::min(lambda, jkr_limit_lambda));
    scales_ = maugis::scales(pair.effective_radius(), pair.effective_modulus(), gamma);
  }

  std::string_view name() const override { return "maugis"; }

  ContactPoint at_force(double force) const override {
    const double f_c = curve_->pull_off().force * scales_.force;
    require_at_least("force", force, f_c, "force >= the Maugis-Dugdale pull-off force ", " N");
    try {
      return to_si(curve_->at_force(std::max(force / scales_.force, curve_->pull_off().force)));
    } catch (const NumericalError&) {
      throw InvalidArgument("force", format_value(force), "a force whose contact state is within double precision");
    }
  }

  ContactPoint at_overlap(double overlap) const override {
    const double delta_c = curve_->min_overlap().overlap * scales_.overlap;
    require_at_least("overlap", overlap, delta_c,
                     "overlap >= ", " m (Maugis-Dugdale contact breaks at more negative overlap)");
    try {
      return to_si(curve_->at_overlap(std::max(overlap / scales_.overlap, curve_->min_overlap().overlap)));
    } catch (const NumericalError&) {
      throw InvalidArgument("overlap", format_value(overlap), "an overlap whose contact state is within double precision");
    }
  }

  ContactPoint at_contact_radius(double a) const override {
    require_non_negative("contact_radius", a, "contact radius [m]");
    return to_si(curve_->at_contact_radius(a / scales_.length));
  }

  std::optional<AdhesionSummary> adhesion() const override {
    AdhesionSummary s;
    s.pull_off_force = curve_->pull_off().force * scales_.force;
    s.pull_off_contact_radius = curve_->pull_off().contact_radius * scales_.length;
    const maugis::Point zero = curve_->at_force(0.0);
    s.zero_load_contact_radius = zero.contact_radius * scales_.length;
    s.zero_load_overlap = zero.overlap * scales_.overlap;
    s.separation_overlap = curve_->min_overlap().overlap * scales_.overlap;
    s.separation_contact_radius = curve_->min_overlap().contact_radius * scales_.length;
    return s;
  }

  private:
  ContactPoint to_si(const maugis::Point& p) const {
    return {p.contact_radius * scales_.length, p.overlap * scales_.overlap, p.force * scales_.force};
  }

  std::optional<maugis::Curve> curve_;
  maugis::Scales scales_;
};

}  // namespace

std::unique_ptr<ContactLaw> make_maugis_law(const Pair& pair, double z0) {
  return std::make_unique<MaugisLaw>(pair, z0);
}

}  // namespace bounce::contact

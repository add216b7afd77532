#include "bounce/contact/maugis_branch.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::contact::maugis {

namespace {

constexpr double pi = std::numbers::pi;

// (MD1)'s brackets (maugis.cpp writes them for its own solve) and their slopes in s.
double first_bracket(double s) {  // (s^2 - 1) atan s + s, without cancellation for small s
  if (s < 1e-2) {
    const double s2 = s * s;
    const double s_minus_atan = s * s2 * (1.0 / 3.0 - s2 * (0.2 - s2 * (1.0 / 7.0 - s2 / 9.0)));
    return s2 * std::atan(s) + s_minus_atan;
  }
  return (s * s - 1.0) * std::atan(s) + s;
}
double second_bracket(double s) { return s * std::atan(s) - s * s / (1.0 + std::sqrt(1.0 + s * s)); }
double first_slope(double s) { return 2.0 * s * std::atan(s) + 2.0 * s * s / (1.0 + s * s); }
double second_slope(double s) { return std::atan(s) + s / (1.0 + s * s) - s / std::sqrt(1.0 + s * s); }

// A contact state at zone parameter s = sqrt(m^2 - 1) = tan(theta), with dDelta/ds.
struct Contact {
  BranchPoint point;
  double overlap_slope = 0.0;  // dDelta/ds
};

Contact contact_at(double lambda, double s) {  // (MD1)-(MD3), explicit in A at given s
  const double qa = 0.5 * lambda * first_bracket(s), qb = 4.0 / 3.0 * lambda * lambda * second_bracket(s);
  const double a = 2.0 / (qb + std::sqrt(qb * qb + 4.0 * qa));  // the positive root of qa A^2 + qb A = 1
  const double dqa = 0.5 * lambda * first_slope(s), dqb = 4.0 / 3.0 * lambda * lambda * second_slope(s);
  const double da = -(dqa * a * a + dqb * a) / (2.0 * qa * a + qb);
  Contact c;
  c.point.contact_radius = a;
  c.point.zone_radius = a * std::sqrt(1.0 + s * s);
  c.point.force = a * a * a - lambda * a * a * (s + (1.0 + s * s) * std::atan(s));  // (MD2)
  c.point.overlap = a * a - 4.0 / 3.0 * lambda * a * s;                            // (MD3)
  c.overlap_slope = 2.0 * a * da - 4.0 / 3.0 * lambda * (da * s + a);
  return c;
}

// Before contact: the zone alone, of radius C (header).
BranchPoint zone_alone(double lambda, double zone) {
  BranchPoint p;
  p.zone_radius = zone;
  p.force = -0.5 * pi * lambda * zone * zone;
  p.overlap = 0.5 * zone * zone - 8.0 * lambda / (3.0 * pi) * zone - 2.0 / (pi * lambda);
  return p;
}
// Its energy, int P dDelta from C = 0: -(pi lambda/2) (C^4/4 - (8 lambda/(9 pi)) C^3).
double zone_alone_energy(double lambda, double zone) {
  return -0.5 * pi * lambda * (0.25 * zone * zone * zone * zone - 8.0 * lambda / (9.0 * pi) * zone * zone * zone);
}
// Where the zone's overlap is least, dDelta/dC = C - 8 lambda/(3 pi) = 0.
double zone_fold(double lambda) { return 8.0 * lambda / (3.0 * pi); }

// The contact part's energy: int P dDelta over x = ln s, whose integrand -P (dDelta/ds) s falls like
// e^-x as s -> inf (A s -> C0, dDelta/ds ~ 1/s^2): above x = 40 what is left is below 1e-17 of it.
constexpr double work_top = 40.0, work_spacing = 0.05, work_bottom = -40.0;
double work_density(double lambda, double x) {
  const double s = std::exp(x);
  const Contact c = contact_at(lambda, s);
  return -c.point.force * c.overlap_slope * s;
}
double work_over(double lambda, double from, double to, bool adaptive) {
  auto f = [&](double x) { return work_density(lambda, x); };
  if (!adaptive) return boost::math::quadrature::gauss_kronrod<double, 15>::integrate(f, from, to, 0, 0.0);
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, from, to, 15, 1e-14);
}

template <class F>
double minimum(F f, double lo, double hi) {
  std::uintmax_t iterations = 200;
  return boost::math::tools::brent_find_minima(f, lo, hi, std::numeric_limits<double>::digits / 2, iterations).first;
}

}  // namespace

Branch::Branch(double lambda) : lambda_(lambda) {
  require_positive("lambda", lambda, "Maugis parameter lambda");
  const double qa = 0.25 * pi * lambda, qb = 2.0 / 3.0 * (pi - 2.0) * lambda * lambda;
  zone_at_touch_ = 2.0 / (qb + std::sqrt(qb * qb + 4.0 * qa));
  snap_overlap_ = -2.0 / (pi * lambda);
  // The fold: before contact where the zone's own fold comes first, else in contact (Delta's one
  // minimum over theta; Brent's search to half the digits of theta is Delta to all of them).
  constexpr double top = 0.5 * pi * (1.0 - 1e-12);
  if (zone_fold(lambda) < zone_at_touch_) {
    fold_place_ = {false, zone_fold(lambda)};
  } else {
    fold_place_ = {true, minimum([&](double t) { return contact_at(lambda, std::tan(t)).point.overlap; }, 1e-300, top)};
  }
  fold_ = at(fold_place_);
  // The pull-off: the least force beyond the fold (before contact P falls as C grows, so it is in
  // contact, or at C0).
  const double below = fold_place_.contact ? fold_place_.value : top;
  pull_off_place_ = {true, minimum([&](double t) { return contact_at(lambda, std::tan(t)).point.force; }, 1e-300, below)};
  pull_off_ = at(pull_off_place_);
}

const std::vector<double>& Branch::work() const {
  std::call_once(work_made_, [this] {
    const auto cells = static_cast<std::size_t>((work_top - work_bottom) / work_spacing);
    work_.assign(cells + 1, 0.0);
    for (std::size_t i = 1; i <= cells; ++i) {
      const double upper = work_top - double(i - 1) * work_spacing;
      work_[i] = work_[i - 1] + work_over(lambda_, upper - work_spacing, upper, false);
    }
  });
  return work_;
}

BranchPoint Branch::at(const Place& place) const {
  if (!place.contact) return zone_alone(lambda_, place.value);
  return contact_at(lambda_, std::tan(place.value)).point;
}

double Branch::order(const Place& place) const {
  return place.contact ? 2.0 - 2.0 * place.value / pi : place.value / zone_at_touch_;
}

Place Branch::place(double tau) const {
  if (tau <= 1.0) return {false, tau * zone_at_touch_};
  return {true, 0.5 * pi * (2.0 - tau)};
}

Place Branch::place_at_overlap(double overlap) const {
  if (!(overlap > fold_.overlap)) return fold_place_;
  // Before contact, on the zone's rising part: the larger root of C^2/2 - b C - h0 = Delta.
  const double b = zone_fold(lambda_);
  if (!fold_place_.contact && overlap <= zone_alone(lambda_, zone_at_touch_).overlap) {
    return {false, std::min(b + std::sqrt(b * b + 2.0 * (overlap - snap_overlap_)), zone_at_touch_)};
  }
  // In contact: Delta falls as s grows, from +inf at s = 0 to the fold (or to C0's at s = inf);
  // solved in log s.
  const double s_top = fold_place_.contact ? std::tan(fold_place_.value) : std::tan(0.5 * pi * (1.0 - 1e-15));
  auto residual = [&](double log_s) { return contact_at(lambda_, std::exp(log_s)).point.overlap - overlap; };
  const double hi_log = std::log(s_top);
  // An overlap within rounding of the fold's: s_top's round trip through the log can land where
  // Delta is a hair above it. The fold is the state there.
  if (residual(hi_log) >= 0.0) return fold_place_.contact ? fold_place_ : Place{true, std::atan(s_top)};
  double lo_log = hi_log - 1.0;
  while (residual(lo_log) < 0.0) {
    lo_log -= 2.0 * (hi_log - lo_log);
    if (lo_log < -700.0) throw NumericalError("Maugis-Dugdale: the overlap is beyond double precision");
  }
  std::uintmax_t iterations = 200;
  try {
    const auto [x0, x1] = boost::math::tools::toms748_solve(residual, lo_log, hi_log,
                                                            boost::math::tools::eps_tolerance<double>(52), iterations);
    return {true, std::atan(std::exp(0.5 * (x0 + x1)))};
  } catch (const std::domain_error& e) {  // Boost's "do not bracket": bounce's own error
    throw NumericalError(std::string("Maugis-Dugdale: no state found at this overlap (") + e.what() + ")");
  }
}

double Branch::zero_force_overlap() const {
  // P rises from the pull-off (its least) as the contact grows (s falls): one root below s_pull.
  auto force = [&](double log_s) { return contact_at(lambda_, std::exp(log_s)).point.force; };
  const double hi = std::log(std::tan(pull_off_place_.value));
  double lo = hi - 1.0;
  while (force(lo) < 0.0) lo -= 2.0 * (hi - lo);
  std::uintmax_t iterations = 200;
  const auto [x0, x1] = boost::math::tools::toms748_solve(force, lo, hi, boost::math::tools::eps_tolerance<double>(52),
                                                          iterations);
  return contact_at(lambda_, std::exp(0.5 * (x0 + x1))).point.overlap;
}

double Branch::energy(const Place& place) const {
  if (!place.contact) return zone_alone_energy(lambda_, place.value);
  // U(C0) + int from x = ln s to the top of -P dDelta/dx: the table to the node above x, the rule
  // over the rest of x's cell (adaptive beyond the table's ends).
  const double x = std::log(std::tan(place.value));
  const double base = zone_alone_energy(lambda_, zone_at_touch_);
  if (x >= work_top) return base - work_over(lambda_, work_top, x, true);
  const std::vector<double>& work = this->work();
  const double cells = (work_top - x) / work_spacing;
  if (cells >= double(work.size() - 1)) return base + work.back() + work_over(lambda_, x, work_bottom, true);
  const auto i = static_cast<std::size_t>(cells);
  return base + work[i] + work_over(lambda_, x, work_top - double(i) * work_spacing, false);
}

double Branch::surface_energy_at_overlap(double overlap, const Branch& down, const Branch& up) const {
  // U_S = -C^2 + lambda dU/dlambda at fixed Delta: a central difference of relative step 1e-5
  // (truncation ~1e-10 of U, the quadratures' 1e-13 divided by the step ~1e-8 of U).
  const double derivative = (up.energy_at_overlap(overlap) - down.energy_at_overlap(overlap)) / (up.lambda() - down.lambda());
  const double zone = at_overlap(overlap).zone_radius;
  return -zone * zone + lambda_ * derivative;
}

}  // namespace bounce::contact::maugis

// What a fit's result says about itself (docs/fitting.md, "Warnings"): values on the edge of
// their grid, parameters the data do not determine, a fit with as many parameters as points.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "bounce/analytic/adhesive.hpp"
#include "fit_internal.hpp"

namespace bounce::analysis::detail {

namespace {

// On the edge of its grid: at the edge within the refinement's precision. The refined best is
// exp(log(edge)) (0.0010000000000000002 for an edge of 0.001), and Nelder-Mead pressing on a
// bound stops within its xtol = log(1 + precision) of it.
void warn_about_edges(const FitProblem& p, FitResult& r) {
  const double tolerance = std::log1p(p.precision);
  r.grid_edges.assign(r.profiles.size(), 0);
  for (std::size_t a = 0; a < r.profiles.size(); ++a) {
    const auto& v = r.profiles[a].values;
    if (v.size() < 2 || (r.yield_lower_limit && a + 1 == r.names.size() && p.yield_axis)) continue;
    const double x = std::log(r.best.values[a]);
    const bool lower = x - std::log(v.front()) <= tolerance, upper = std::log(v.back()) - x <= tolerance;
    if (lower || upper) {
      r.grid_edges[a] = lower ? -1 : 1;
      r.warnings.push_back(fmt::format("the best {} lies on the edge of its grid ({:.4g} .. {:.4g}): a limit, not a "
                                       "value; widen the grid to locate it",
                                       r.names[a], v.front(), v.back()));
    }
  }
}

// K13 (28): v_y grows as Y^(5/2). Where every measured speed lies below the yield velocity at
// the best Y, e_P = 1 at every point and chi^2 is the same for every Y whose v_y reaches the
// fastest speed: the data say Y >= that, nothing more (the best Y was any value of that
// stretch the search happened to end on).
void limit_free_yield(const FitProblem& p, FitResult& r) {
  if (!p.yield_axis) return;
  double v_max = 0.0;
  for (const Measurement& m : p.data.points) v_max = std::max(v_max, m.velocity);
  const double y = r.best.values.back();
  const FitCase c = p.case_at(std::span(r.best.values).first(p.collision_axes.size()));
  const double v_y = analytic::yield_velocity(c.pair.effective_radius(), c.pair.effective_mass(),
                                              c.pair.effective_modulus(), y);
  if (!(v_y >= v_max)) return;
  const double limit = y * std::pow(v_max / v_y, 0.4);
  r.yield_lower_limit = limit;
  r.best.values.back() = limit;
  if (r.weighted_best && r.weighted_best->values.back() >= limit) r.weighted_best->values.back() = limit;
  r.warnings.push_back(fmt::format("{} is not determined: no measured speed reaches the yield velocity (K13 (28)) for "
                                   "{} >= {:.4g} Pa, where chi^2 no longer depends on it; that is a lower limit, not a "
                                   "value (measure faster collisions to fit it)",
                                   r.names.back(), r.names.back(), limit));
}

// A range open at both ends: chi^2 within its threshold over the whole grid.
void warn_about_unconstrained(const FitProblem& p, FitResult& r) {
  for (std::size_t a = 0; a < r.ranges.size(); ++a) {
    const bool yield = p.yield_axis && a + 1 == r.names.size();
    if (r.ranges[a].lo || r.ranges[a].hi || r.profiles[a].values.size() < 2 || (yield && r.yield_lower_limit)) continue;
    r.warnings.push_back(fmt::format("{} is not determined on this grid: chi^2 stays within a factor 2 of its minimum "
                                     "from one end of the grid to the other; its best value is not a measurement",
                                     r.names[a]));
  }
}

}  // namespace

void check_result(const FitProblem& p, FitResult& r) {
  limit_free_yield(p, r);
  warn_about_edges(p, r);
  warn_about_unconstrained(p, r);
  if (p.data.points.size() == r.names.size()) {
    r.warnings.push_back(fmt::format("{} measurements for {} parameters: with as many parameters as points the data "
                                     "cannot test the model (chi^2 = {:.3g} says only how closely it meets them)",
                                     p.data.points.size(), r.names.size(), r.best.chi2));
  }
}

}  // namespace bounce::analysis::detail

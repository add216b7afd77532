// K13 §4.1: chi^2 (31) on a grid of parameter values, the profiles and factor-2 ranges, then
// the refinement (fit_refine.cpp). docs/fitting.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>

#include <fmt/format.h>

#include "bounce/analytic/adhesive.hpp"
#include "bounce/core/error.hpp"
#include "fit_internal.hpp"
#include "parallel.hpp"

namespace bounce::analysis {

ParameterRange profile_range(const Profile& profile, double best_value, double best_chi2, double threshold) {
  struct Sample {
    double value, chi2;
  };
  std::vector<Sample> s;
  for (std::size_t j = 0; j < profile.values.size(); ++j) s.push_back({profile.values[j], profile.chi2[j]});
  const auto at = std::lower_bound(s.begin(), s.end(), best_value, [](const Sample& a, double v) { return a.value < v; });
  std::size_t k = static_cast<std::size_t>(at - s.begin());
  if (at != s.end() && at->value == best_value) {
    at->chi2 = std::min(at->chi2, best_chi2);
  } else {
    s.insert(at, {best_value, best_chi2});
  }
  // Linear in log(value) between the last sample inside and the first outside.
  auto crossing = [&](const Sample& in, const Sample& out) {
    const double t = std::isfinite(out.chi2) ? (threshold - in.chi2) / (out.chi2 - in.chi2) : 0.0;
    return std::exp(std::log(in.value) + std::clamp(t, 0.0, 1.0) * (std::log(out.value) - std::log(in.value)));
  };
  ParameterRange r;
  std::size_t lo = k, hi = k;
  while (lo > 0 && s[lo - 1].chi2 <= threshold) --lo;
  while (hi + 1 < s.size() && s[hi + 1].chi2 <= threshold) ++hi;
  if (lo > 0) r.lo = crossing(s[lo], s[lo - 1]);
  if (hi + 1 < s.size()) r.hi = crossing(s[hi], s[hi + 1]);
  return r;
}

namespace {

using detail::Evaluator;
using detail::PlasticScales;
constexpr double inf = std::numeric_limits<double>::infinity();

// The collision axes' values at flat index i (row-major: the last axis fastest).
std::vector<double> values_at(const std::vector<FitAxis>& axes, std::size_t i) {
  std::vector<double> v(axes.size());
  for (std::size_t a = axes.size(); a-- > 0;) {
    v[a] = axes[a].values[i % axes[a].values.size()];
    i /= axes[a].values.size();
  }
  return v;
}

std::size_t product(const std::vector<FitAxis>& axes) {
  std::size_t n = 1;
  for (const FitAxis& a : axes) n *= a.values.size();
  return n;
}

void check_problem(const FitProblem& p) {
  if (p.collision_axes.empty() && !p.yield_axis) throw InvalidArgument("fit", "(nothing)", "at least one parameter to fit");
  const std::size_t k = p.collision_axes.size() + (p.yield_axis ? 1 : 0);
  if (p.data.points.size() < k) {
    throw InvalidArgument("data", p.data.source,
                          fmt::format("at least as many measurements as fitted parameters ({} measurements, {} "
                                      "parameters)",
                                      p.data.points.size(), k));
  }
  std::vector<FitAxis> all = p.collision_axes;
  if (p.yield_axis) all.push_back(*p.yield_axis);
  for (const FitAxis& a : all) {
    if (a.values.empty()) throw InvalidArgument("grid", a.name, "at least one value per fitted parameter");
    for (std::size_t j = 0; j < a.values.size(); ++j) {
      if (!(a.values[j] > 0.0) || !std::isfinite(a.values[j]) || (j > 0 && !(a.values[j] > a.values[j - 1]))) {
        throw InvalidArgument("grid", a.name, "increasing values > 0 and finite");
      }
    }
  }
  // A million grid points of the collision axes are 3e7 collisions against 30 speeds (about
  // two hours on two cores); 1e8 chi^2 values are 800 MB. Beyond either, a grid is a typo.
  constexpr double max_collision_points = 1e6, max_values = 1e8;
  double points = 1.0;
  for (const FitAxis& a : p.collision_axes) points *= static_cast<double>(a.values.size());
  const double values = points * (p.yield_axis ? static_cast<double>(p.yield_axis->values.size()) : 1.0);
  if (points > max_collision_points || values > max_values) {
    throw InvalidArgument("grid", fmt::format("{:.3g} points ({:.3g} with the yield axis)", points, values),
                          "at most 1e6 points of the collision parameters and 1e8 in all");
  }
  if (!(p.precision > 0.0 && p.precision < 1.0)) {
    throw InvalidArgument("precision", fmt::format("{}", p.precision), "0 < precision < 1");
  }
}

// The grid's e_A (per collision point) and the chi^2 of every grid point.
struct GridValues {
  std::vector<GridPoint> points;
  std::vector<double> chi2, weighted;  // per (collision point, yield), +inf where failed
  std::size_t failed = 0;
  std::string first_failure;
};

PlasticScales scales_of(const GridPoint& g) { return {g.radius, g.mass, g.modulus}; }

GridPoint integrate_point(const FitProblem& p, const Evaluator& ev, std::size_t i, unsigned threads) {
  GridPoint g;
  PlasticScales scales;
  if (auto e = ev.adhesive(values_at(p.collision_axes, i), threads, scales, g.failure)) {
    g.cor = std::move(*e);
  } else if (g.failure.empty()) {
    g.failure = "a collision failed";
  }
  g.radius = scales.radius, g.mass = scales.mass, g.modulus = scales.modulus;
  return g;
}

std::vector<GridPoint> integrate_grid(const FitProblem& p, const Evaluator& ev) {
  const std::size_t n = product(p.collision_axes);
  std::vector<GridPoint> points(n);
  ev.set_progress_total(n * ev.speeds().size());
  detail::parallel_for(n, p.threads, [&](std::size_t i, unsigned) { points[i] = integrate_point(p, ev, i, 1); });
  return points;
}

void count_failures(GridValues& g, const Evaluator& ev) {
  for (const GridPoint& point : g.points) {
    if (point.failure.empty() && point.cor.size() == ev.speeds().size()) continue;
    if (g.failed++ == 0) g.first_failure = point.failure.empty() ? "a point with the wrong number of speeds" : point.failure;
  }
}

bool failed(const GridPoint& g, const Evaluator& ev) { return !g.failure.empty() || g.cor.size() != ev.speeds().size(); }

// chi^2 at every (collision point, yield value). e_P depends on the pair's scales, the yield
// strength and the speed only: one table for the grid when every point has the same pair
// (fitting gamma, T_vis, A, z0 or k), else computed per point.
void grid_chi2(const FitProblem& p, const Evaluator& ev, GridValues& g, FitResult& r) {
  using Clock = std::chrono::steady_clock;
  const std::size_t n = g.points.size(), ny = p.yield_axis ? p.yield_axis->values.size() : 1;
  const bool weighted = p.data.has_errors();
  auto yield_at = [&](std::size_t y) { return p.yield_axis ? std::optional(p.yield_axis->values[y]) : std::nullopt; };
  const auto first = std::find_if(g.points.begin(), g.points.end(), [&](const GridPoint& x) { return !failed(x, ev); });
  const PlasticScales common = scales_of(*first);
  const bool shared = std::all_of(g.points.begin(), g.points.end(),
                                  [&](const GridPoint& x) { return failed(x, ev) || scales_of(x) == common; });
  auto start = Clock::now();
  std::vector<std::vector<double>> e_p(ny);
  if (shared) {
    for (std::size_t y = 0; y < ny; ++y) e_p[y] = ev.plastic_cors(common, yield_at(y));
  }
  r.plastic_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  start = Clock::now();
  g.chi2.assign(n * ny, inf);
  if (weighted) g.weighted.assign(n * ny, inf);
  detail::parallel_for(n, p.threads, [&](std::size_t i, unsigned) {
    if (failed(g.points[i], ev)) return;
    std::vector<double> cor(p.data.points.size());
    for (std::size_t y = 0; y < ny; ++y) {
      ev.combine(g.points[i].cor, shared ? e_p[y] : ev.plastic_cors(scales_of(g.points[i]), yield_at(y)), cor);
      g.chi2[i * ny + y] = ev.objective(cor, false);
      if (weighted) g.weighted[i * ny + y] = ev.objective(cor, true);
    }
  });
  r.chi2_seconds = std::chrono::duration<double>(Clock::now() - start).count();
}

// Profiles of a chi^2 grid: per axis (collision axes, then yield), the minimum over the others.
std::vector<Profile> profiles(const FitProblem& p, const std::vector<double>& chi2) {
  std::vector<FitAxis> axes = p.collision_axes;
  if (p.yield_axis) axes.push_back(*p.yield_axis);
  std::vector<Profile> out;
  for (const FitAxis& a : axes) out.push_back({a.values, std::vector<double>(a.values.size(), inf)});
  for (std::size_t flat = 0; flat < chi2.size(); ++flat) {
    std::size_t rest = flat;
    for (std::size_t a = axes.size(); a-- > 0;) {
      const std::size_t j = rest % axes[a].values.size();
      rest /= axes[a].values.size();
      out[a].chi2[j] = std::min(out[a].chi2[j], chi2[flat]);
    }
  }
  return out;
}

// The grid point with the least chi^2 (the first of equals: deterministic).
FitMinimum grid_minimum(const FitProblem& p, const std::vector<double>& chi2) {
  const std::size_t ny = p.yield_axis ? p.yield_axis->values.size() : 1;
  const auto best = static_cast<std::size_t>(std::min_element(chi2.begin(), chi2.end()) - chi2.begin());
  FitMinimum m;
  m.values = values_at(p.collision_axes, best / ny);
  if (p.yield_axis) m.values.push_back(p.yield_axis->values[best % ny]);
  m.chi2 = chi2[best];
  return m;
}

// The yield strength's profile: the grid's, and where lower the slice through the refined
// minimum (its collision values held: no collisions beyond one set of e_A), which follows
// the minimum between the coarse values of the collision axes.
Profile yield_profile(const Evaluator& ev, const Profile& grid, const FitMinimum& best, bool weighted) {
  const FitProblem& p = ev.problem();
  Profile out = grid;
  PlasticScales scales;
  std::string failure;
  const auto e_a = ev.adhesive(std::span(best.values).first(p.collision_axes.size()), p.threads, scales, failure);
  if (!e_a) return out;
  std::vector<double> cor(p.data.points.size());
  for (std::size_t j = 0; j < out.values.size(); ++j) {
    ev.model_cor(scales, *e_a, out.values[j], cor);
    out.chi2[j] = std::min(out.chi2[j], ev.objective(cor, weighted));
  }
  return out;
}

// The ranges where chi^2 <= threshold. Refined: each parameter by its own profile near the
// minimum (detail::refined_range: the others re-optimised), or, with Y alone fitted, its
// exact profile on its grid (yield_profile). On the grid alone (no refinement): the grid's
// profiles, interpolated.
std::vector<ParameterRange> ranges(const Evaluator& ev, const std::vector<Profile>& prof, const FitMinimum& best,
                                   double threshold, bool weighted) {
  const FitProblem& p = ev.problem();
  std::vector<ParameterRange> out;
  for (std::size_t a = 0; a < prof.size(); ++a) {
    const bool yield = a == p.collision_axes.size();
    if (!p.refine) {
      out.push_back(profile_range(prof[a], best.values[a], best.chi2, threshold));
    } else if (yield && p.collision_axes.empty()) {
      out.push_back(profile_range(yield_profile(ev, prof[a], best, weighted), best.values[a], best.chi2, threshold));
    } else {
      out.push_back(detail::refined_range(ev, best, a, threshold, weighted));
    }
  }
  return out;
}

// The fit from the grid's points (the rest of K13 §4.1 and the refinements).
FitResult finish(const FitProblem& p, const Evaluator& ev, std::vector<GridPoint> points, FitResult r) {
  for (const FitAxis& a : p.collision_axes) r.names.push_back(a.name);
  if (p.yield_axis) r.names.push_back(p.yield_axis->name);
  for (const FitAxis& a : p.collision_axes) r.grid_shape.push_back(a.values.size());
  if (p.yield_axis) r.grid_shape.push_back(p.yield_axis->values.size());
  if (points.size() != product(p.collision_axes)) {
    throw std::logic_error(fmt::format("{} grid points for a grid of {}", points.size(), product(p.collision_axes)));
  }
  GridValues g{std::move(points), {}, {}, 0, {}};
  count_failures(g, ev);
  r.failed_trials = g.failed;
  if (g.failed == g.points.size()) {
    throw NumericalError(fmt::format("no trial of the grid could be evaluated; the first failure: {}", g.first_failure));
  }
  if (g.failed > 0) {
    r.warnings.push_back(fmt::format("{} of {} grid points failed and count as chi^2 = inf; the first: {}", g.failed,
                                     g.points.size(), g.first_failure));
  }
  grid_chi2(p, ev, g, r);
  r.profiles = profiles(p, g.chi2);
  r.grid_best = grid_minimum(p, g.chi2);

  const auto refine_start = std::chrono::steady_clock::now();
  ev.set_progress_total(0);  // the refinement and the ranges: collisions counted, no total
  const std::size_t before = ev.collisions();
  r.best = p.refine ? detail::refine(ev, r.grid_best, false, r.cor) : r.grid_best;
  if (!p.refine || r.cor.empty()) {
    PlasticScales scales;
    std::string failure;
    const auto e_a = ev.adhesive(std::span(r.best.values).first(p.collision_axes.size()), p.threads, scales, failure);
    if (!e_a) throw NumericalError("the collisions at the best grid point failed: " + failure);
    r.cor.assign(p.data.points.size(), 0.0);
    ev.model_cor(scales, *e_a, p.yield_axis ? std::optional(r.best.values.back()) : std::nullopt, r.cor);
  }
  r.ranges = ranges(ev, r.profiles, r.best, 2.0 * r.best.chi2, false);  // K13 §4.1: within a factor 2
  if (p.data.has_errors()) {
    r.weighted_profiles = profiles(p, g.weighted);
    const FitMinimum start = grid_minimum(p, g.weighted);
    std::vector<double> unused;
    r.weighted_best = p.refine ? detail::refine(ev, start, true, unused) : start;
    r.intervals = ranges(ev, r.weighted_profiles, *r.weighted_best, r.weighted_best->chi2 + 1.0, true);  // Delta chi^2 = 1
  }
  r.refine_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - refine_start).count();
  r.collisions = r.grid_collisions + (ev.collisions() - before);
  if (p.keep_grid) r.chi2_grid = std::move(g.chi2);
  detail::check_result(p, r);
  return r;
}

}  // namespace

std::size_t grid_point_count(const FitProblem& p) {
  check_problem(p);  // a batch counts its blocks first: a grid too large is refused here
  return product(p.collision_axes);
}

std::vector<GridPoint> integrate_grid_points(const FitProblem& p, std::size_t first, std::size_t count) {
  check_problem(p);
  if (first > product(p.collision_axes) || count > product(p.collision_axes) - first) {
    throw std::out_of_range("grid points beyond the grid");
  }
  const Evaluator ev(p);
  std::vector<GridPoint> out(count);
  detail::parallel_for(count, p.threads, [&](std::size_t i, unsigned) { out[i] = integrate_point(p, ev, first + i, 1); });
  return out;
}

FitResult fit(const FitProblem& p, std::vector<GridPoint> points) {
  check_problem(p);
  const Evaluator ev(p);
  FitResult r;
  r.grid_collisions = points.size() * ev.speeds().size();
  return finish(p, ev, std::move(points), std::move(r));
}

FitResult fit(const FitProblem& p) {
  check_problem(p);
  const Evaluator ev(p);
  FitResult r;
  const auto grid_start = std::chrono::steady_clock::now();
  std::vector<GridPoint> points = integrate_grid(p, ev);
  r.collision_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - grid_start).count();
  r.collision_cpu_seconds = ev.collision_seconds();
  r.grid_collisions = ev.collisions();
  return finish(p, ev, std::move(points), std::move(r));
}

}  // namespace bounce::analysis

// The grid minimum refined (docs/fitting.md): Nelder-Mead (NLopt) in the logarithms of the
// collision parameters inside the grid's box, with the yield strength, which costs no
// collisions, set to its best value for every trial (its grid, then Brent's method).
#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/tools/minima.hpp>
#include <nlopt.hpp>

#include "fit_internal.hpp"

namespace bounce::analysis::detail {

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
// A budget of trials per free dimension: past it the refinement ends with the best trial
// found (Nelder-Mead usually meets the precision well before).
constexpr int trials_per_dimension = 150;
// A point of a profile re-optimises the other collision axes from a neighbouring point's
// optimum: a few dozen trials per dimension.
constexpr int profile_trials_per_dimension = 40;
// Bisections of a range's end: 1/64 of the last step out (at least a quarter grid step).
constexpr int bisections = 6;
}  // namespace

FitMinimum best_yield(const Evaluator& ev, const PlasticScales& scales, std::span<const double> e_a,
                      const FitAxis& yield, bool weighted) {
  std::vector<double> cor(ev.problem().data.points.size());
  auto chi2 = [&](double y) {
    ev.model_cor(scales, e_a, y, cor);
    return ev.objective(cor, weighted);
  };
  const auto& v = yield.values;
  std::size_t best = 0;
  double best_chi2 = inf;
  for (std::size_t j = 0; j < v.size(); ++j) {
    const double c = chi2(v[j]);
    if (c < best_chi2) best_chi2 = c, best = j;  // the first of equals: deterministic
  }
  FitMinimum m{{v[best]}, best_chi2};
  if (v.size() < 3) return m;
  const double lo = std::log(v[best == 0 ? 0 : best - 1]), hi = std::log(v[std::min(best + 1, v.size() - 1)]);
  const auto [x, c] = boost::math::tools::brent_find_minima([&](double s) { return chi2(std::exp(s)); }, lo, hi, 40);
  if (c < m.chi2) m = {{std::exp(x)}, c};
  return m;
}

namespace {

// chi^2 of a trial: the logarithms of the free collision values (the axes with more than one
// value; the others keep theirs).
struct Objective {
  const Evaluator& ev;
  bool weighted;
  std::vector<double> fixed;       // the collision values of the start
  std::vector<std::size_t> free;   // the axes the optimiser moves
  FitMinimum best{{}, inf};        // the best trial so far (collision values, then yield)
  std::vector<double> cor_at_best;
  std::optional<double> fixed_yield;  // a profile of Y: this value, not its best

  double operator()(const std::vector<double>& log_values) {
    std::vector<double> values = fixed;
    for (std::size_t k = 0; k < free.size(); ++k) values[free[k]] = std::exp(log_values[k]);
    PlasticScales scales;
    std::string failure;
    const auto e_a = ev.adhesive(values, ev.problem().threads, scales, failure);
    if (!e_a) return inf;  // a failed trial is the worst possible
    const auto& yield = ev.problem().yield_axis;
    FitMinimum m{values, 0.0};
    std::optional<double> y;
    if (fixed_yield) {
      m.values.push_back(*fixed_yield);
      y = fixed_yield;
    } else if (yield) {
      const FitMinimum by = best_yield(ev, scales, *e_a, *yield, weighted);
      m.values.push_back(by.values.front());
      y = by.values.front();
    }
    std::vector<double> cor(ev.problem().data.points.size());
    ev.model_cor(scales, *e_a, y, cor);
    m.chi2 = ev.objective(cor, weighted);
    if (m.chi2 < best.chi2) {
      best = m;
      cor_at_best = cor;
    }
    return m.chi2;
  }
};

double call(const std::vector<double>& x, std::vector<double>&, void* data) { return (*static_cast<Objective*>(data))(x); }

// chi^2 minimised over the collision axes `free` (their logarithms, inside the grid's box),
// the others held at `start`'s values; the yield strength set to its best for every trial.
// `steps`: Nelder-Mead's first steps, in grid steps.
FitMinimum minimise(const Evaluator& ev, const std::vector<double>& start, const std::vector<std::size_t>& free,
                    bool weighted, int budget, double steps, std::vector<double>& cor_at_best,
                    std::optional<double> fixed_yield = std::nullopt) {
  const FitProblem& p = ev.problem();
  Objective objective{ev, weighted, start, free, {{}, inf}, {}, fixed_yield};
  std::vector<double> x, lo, hi, step;
  for (std::size_t a : free) {
    const auto& v = p.collision_axes[a].values;
    x.push_back(std::log(start[a]));
    lo.push_back(std::log(v.front()));
    hi.push_back(std::log(v.back()));
    step.push_back(steps * (hi.back() - lo.back()) / static_cast<double>(v.size() - 1));
  }
  objective(x);  // the start, so that the result is never worse than it
  if (!x.empty()) {
    nlopt::opt opt(nlopt::LN_NELDERMEAD, static_cast<unsigned>(x.size()));
    opt.set_lower_bounds(lo);
    opt.set_upper_bounds(hi);
    opt.set_min_objective(call, &objective);
    opt.set_xtol_abs(std::log1p(p.precision));
    opt.set_initial_step(step);
    opt.set_maxeval(budget);
    double value = 0.0;
    try {
      opt.optimize(x, value);
    } catch (const std::exception&) {
      // NLopt's roundoff or forced stops: the best trial, kept by the objective, stands.
    }
  }
  cor_at_best = objective.cor_at_best;
  return objective.best;
}

// The collision axes with more than one value (the others are held).
std::vector<std::size_t> free_axes(const FitProblem& p, std::optional<std::size_t> except = std::nullopt) {
  std::vector<std::size_t> out;
  for (std::size_t a = 0; a < p.collision_axes.size(); ++a) {
    if (p.collision_axes[a].values.size() > 1 && a != except) out.push_back(a);
  }
  return out;
}

}  // namespace

FitMinimum refine(const Evaluator& ev, const FitMinimum& start, bool weighted, std::vector<double>& cor_at_best) {
  const FitProblem& p = ev.problem();
  const std::vector<double> values(start.values.begin(), start.values.begin() + static_cast<long>(p.collision_axes.size()));
  const auto free = free_axes(p);
  return minimise(ev, values, free, weighted, trials_per_dimension * static_cast<int>(free.size()), 1.0, cor_at_best);
}

ParameterRange refined_range(const Evaluator& ev, const FitMinimum& best, std::size_t axis, double threshold,
                             bool weighted) {
  const FitProblem& p = ev.problem();
  const std::size_t collision = p.collision_axes.size();
  const bool yield = axis == collision;  // the yield strength: every collision axis re-optimised
  const auto& grid = yield ? p.yield_axis->values : p.collision_axes[axis].values;
  if (grid.size() < 2) return {grid.front(), grid.front()};
  const std::vector<std::size_t> others = free_axes(p, yield ? std::nullopt : std::optional(axis));
  const int budget = profile_trials_per_dimension * static_cast<int>(std::max<std::size_t>(others.size(), 1));
  const double lo_edge = std::log(grid.front()), hi_edge = std::log(grid.back());
  const double grid_step = (hi_edge - lo_edge) / static_cast<double>(grid.size() - 1);
  std::vector<double> ignored;
  // The profile at log value s: the other collision axes re-optimised from `from` (warm start).
  auto profile = [&](double s, std::vector<double>& from) {
    std::optional<double> fixed_yield;
    (yield ? fixed_yield.emplace() : from[axis]) = std::exp(s);
    const FitMinimum m = minimise(ev, from, others, weighted, budget, 0.5, ignored, fixed_yield);
    if (!m.values.empty()) std::copy(m.values.begin(), m.values.begin() + static_cast<long>(collision), from.begin());
    return m.chi2;
  };
  ParameterRange r;
  for (const int side : {-1, 1}) {
    std::vector<double> inside(best.values.begin(), best.values.begin() + static_cast<long>(collision));
    double s_in = std::log(best.values[axis]), s_out = s_in, delta = grid_step / 4.0;
    const double edge = side < 0 ? lo_edge : hi_edge;
    bool open = false;
    while (true) {  // step out, doubling, until the profile leaves the region or the grid ends
      const double s = side < 0 ? std::max(s_in - delta, edge) : std::min(s_in + delta, edge);
      std::vector<double> trial = inside;
      if (profile(s, trial) <= threshold) {
        s_in = s;
        inside = trial;
        if (s == edge) {
          open = true;
          break;
        }
        delta *= 2.0;
      } else {
        s_out = s;
        break;
      }
    }
    if (open) continue;
    for (int k = 0; k < bisections; ++k) {  // the crossing, to 1/64 of the last step
      const double mid = 0.5 * (s_in + s_out);
      std::vector<double> trial = inside;
      if (profile(mid, trial) <= threshold) {
        s_in = mid;
        inside = trial;
      } else {
        s_out = mid;
      }
    }
    (side < 0 ? r.lo : r.hi) = std::exp(0.5 * (s_in + s_out));
  }
  return r;
}

}  // namespace bounce::analysis::detail

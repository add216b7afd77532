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
    if (yield) {
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

}  // namespace

FitMinimum refine(const Evaluator& ev, const FitMinimum& start, bool weighted, std::vector<double>& cor_at_best) {
  const FitProblem& p = ev.problem();
  Objective objective{ev, weighted, {}, {}, {{}, inf}, {}};
  objective.fixed.assign(start.values.begin(), start.values.begin() + static_cast<long>(p.collision_axes.size()));
  std::vector<double> x, lo, hi, step;
  for (std::size_t a = 0; a < p.collision_axes.size(); ++a) {
    const auto& v = p.collision_axes[a].values;
    if (v.size() < 2) continue;
    objective.free.push_back(a);
    x.push_back(std::log(start.values[a]));
    lo.push_back(std::log(v.front()));
    hi.push_back(std::log(v.back()));
    step.push_back((hi.back() - lo.back()) / static_cast<double>(v.size() - 1));  // one grid step
  }
  const std::size_t dims = x.size();
  objective(x);  // the start, so that the result is never worse than the grid
  if (dims > 0) {
    nlopt::opt opt(nlopt::LN_NELDERMEAD, static_cast<unsigned>(dims));
    opt.set_lower_bounds(lo);
    opt.set_upper_bounds(hi);
    opt.set_min_objective(call, &objective);
    opt.set_xtol_abs(std::log1p(p.precision));
    opt.set_initial_step(step);
    opt.set_maxeval(trials_per_dimension * static_cast<int>(dims));
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

}  // namespace bounce::analysis::detail

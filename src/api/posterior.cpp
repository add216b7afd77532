// A fit's likelihood for Bayesian sampling (api/posterior.hpp).
#include "bounce/api/posterior.hpp"

#include <algorithm>

#include "bounce/analysis/likelihood.hpp"
#include "bounce/core/error.hpp"
#include "fit_plan.hpp"

namespace bounce::api {

Likelihood::Likelihood(const Inputs& inputs, const analysis::Experiment& data) : job_(inputs, data) {}

std::vector<std::string> Likelihood::names() const {
  std::vector<std::string> out;
  const analysis::FitProblem& p = job_.problem();
  for (const analysis::FitAxis& a : p.collision_axes) out.push_back(a.name);
  if (p.yield_axis) out.push_back(p.yield_axis->name);
  return out;
}

// The prior of a yield strength ends at the theoretical bound 0.2 E_soft (K13 Fig 7 (b),
// fit_plan.hpp), where the fit's default grid goes on to 1 E_soft to see where no collision yields.
std::vector<std::array<double, 2>> Likelihood::ranges() const {
  std::vector<std::array<double, 2>> out;
  const analysis::FitProblem& p = job_.problem();
  std::vector<double> first;
  for (const analysis::FitAxis& a : p.collision_axes) {
    out.push_back({a.values.front(), a.values.back()});
    first.push_back(a.values.front());
  }
  if (p.yield_axis) {
    const double bound = detail::theoretical_yield_over_e_soft * p.case_at(first).pair.soft_modulus();
    out.push_back({p.yield_axis->values.front(), std::min(p.yield_axis->values.back(), bound)});
  }
  return out;
}

std::vector<double> Likelihood::evaluate(std::span<const double> values, std::size_t rows, unsigned threads) const {
  const std::size_t width = names().size();
  if (values.size() != rows * width) {
    throw InvalidArgument("values", std::to_string(values.size()) + " numbers",
                          std::to_string(rows) + " rows of " + std::to_string(width) + " parameters");
  }
  return analysis::log_likelihoods(job_.problem(), values, rows, threads);
}

bool Likelihood::weighted() const { return job_.problem().data.has_errors(); }

}  // namespace bounce::api

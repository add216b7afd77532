// A fit's likelihood for Bayesian sampling (api/posterior.hpp).
#include "bounce/api/posterior.hpp"

#include "bounce/analysis/likelihood.hpp"
#include "bounce/core/error.hpp"

namespace bounce::api {

Likelihood::Likelihood(const Inputs& inputs, const analysis::Experiment& data) : job_(inputs, data) {}

std::vector<std::string> Likelihood::names() const {
  std::vector<std::string> out;
  const analysis::FitProblem& p = job_.problem();
  for (const analysis::FitAxis& a : p.collision_axes) out.push_back(a.name);
  if (p.yield_axis) out.push_back(p.yield_axis->name);
  return out;
}

std::vector<std::array<double, 2>> Likelihood::ranges() const {
  std::vector<std::array<double, 2>> out;
  const analysis::FitProblem& p = job_.problem();
  for (const analysis::FitAxis& a : p.collision_axes) out.push_back({a.values.front(), a.values.back()});
  if (p.yield_axis) out.push_back({p.yield_axis->values.front(), p.yield_axis->values.back()});
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

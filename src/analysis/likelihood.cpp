// The likelihood of a fit's trial (docs/fitting.md, "Posteriors").
#include "bounce/analysis/likelihood.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "fit_internal.hpp"
#include "parallel.hpp"

namespace bounce::analysis {

namespace {

double log_likelihood(const detail::Evaluator& ev, std::span<const double> values) {
  const FitProblem& p = ev.problem();
  const std::size_t collision_axes = p.collision_axes.size();
  if (values.size() != collision_axes + (p.yield_axis ? 1 : 0)) {
    throw std::logic_error("log_likelihood: one value per fitted parameter");
  }
  detail::PlasticScales scales;
  std::string failure;
  const auto e_a = ev.adhesive(values.first(collision_axes), 1, scales, failure);
  if (!e_a) return -std::numeric_limits<double>::infinity();
  std::vector<double> cor(p.data.points.size());
  const std::optional<double> yield = p.yield_axis ? std::optional(values[collision_axes]) : std::nullopt;
  ev.model_cor(scales, *e_a, yield, cor);  // K13 (30)
  if (p.data.has_errors()) return -0.5 * weighted_chi2(p.data, cor);
  // K13 (31): RSS = N chi^2; a trial through every point (RSS 0, data without noise) is held at
  // the least normal double, not at +inf.
  const double n = static_cast<double>(cor.size());
  const double rss = std::max(n * mean_squared_residual(p.data, cor), std::numeric_limits<double>::min());
  return -0.5 * n * std::log(rss);
}

}  // namespace

double log_likelihood(const FitProblem& problem, std::span<const double> values) {
  return log_likelihood(detail::Evaluator(problem), values);
}

std::vector<double> log_likelihoods(const FitProblem& problem, std::span<const double> values, std::size_t rows,
                                    unsigned threads) {
  if (rows == 0) return {};
  if (values.size() % rows != 0) throw std::logic_error("log_likelihoods: values are rows x parameters");
  const std::size_t width = values.size() / rows;
  const detail::Evaluator ev(problem);
  std::vector<double> out(rows);
  detail::parallel_for(rows, threads, [&](std::size_t i, unsigned) {
    out[i] = log_likelihood(ev, values.subspan(i * width, width));
  });
  return out;
}

}  // namespace bounce::analysis

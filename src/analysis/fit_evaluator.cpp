// The evaluation of a fit's trial (docs/fitting.md): each trial's collisions, the plastic COR of
// K13 (28)-(29) combined by (30), and chi^2 (31).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "bounce/analytic/adhesive.hpp"
#include "bounce/core/error.hpp"
#include "fit_internal.hpp"
#include "parallel.hpp"

namespace bounce::analysis {

namespace detail {

namespace {
using Clock = std::chrono::steady_clock;

long long nanoseconds_since(Clock::time_point start) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
}
}  // namespace

PlasticScales plastic_scales(const Pair& pair) {
  return {pair.effective_radius(), pair.effective_mass(), pair.effective_modulus()};
}

Evaluator::Evaluator(const FitProblem& problem) : problem_(problem) {
  for (const Measurement& m : problem.data.points) speeds_.push_back(m.velocity);
  std::sort(speeds_.begin(), speeds_.end());
  speeds_.erase(std::unique(speeds_.begin(), speeds_.end()), speeds_.end());
  for (const Measurement& m : problem.data.points) {
    speed_of_point_.push_back(
        static_cast<std::size_t>(std::lower_bound(speeds_.begin(), speeds_.end(), m.velocity) - speeds_.begin()));
  }
}

std::optional<std::vector<double>> Evaluator::adhesive(std::span<const double> values, unsigned threads,
                                                       PlasticScales& scales, std::string& failure) const {
  const FitCase c = problem_.case_at(values);
  scales = plastic_scales(c.pair);
  std::vector<double> e_a(speeds_.size(), 0.0);
  std::vector<std::string> failures(speeds_.size());
  parallel_for(speeds_.size(), threads, [&](std::size_t u, unsigned) {
    const auto start = Clock::now();
    try {
      e_a[u] = analysis::cor(c.pair, c.model, speeds_[u], c.options);
    } catch (const NumericalError& e) {
      failures[u] = e.what();
    }
    collision_nanoseconds_ += nanoseconds_since(start);
    ++collisions_;
    report_collision();  // may throw (an interrupted fit): parallel_for stops and rethrows it
  });
  for (const std::string& f : failures) {
    if (!f.empty()) {
      failure = f;
      return std::nullopt;
    }
  }
  return e_a;
}

void Evaluator::set_progress_total(std::size_t total) const {
  const std::lock_guard lock(progress_mutex_);
  progress_total_ = total;
}

void Evaluator::report_collision() const {
  if (!problem_.progress) return;
  const std::lock_guard lock(progress_mutex_);
  problem_.progress(collisions_.load(), progress_total_);
}

std::vector<double> Evaluator::plastic_cors(const PlasticScales& s, std::optional<double> yield) const {
  std::vector<double> e_p(speeds_.size(), 1.0);
  if (!yield) return e_p;
  const double v_y = analytic::yield_velocity(s.radius, s.mass, s.modulus, *yield);  // K13 (28)
  for (std::size_t u = 0; u < speeds_.size(); ++u) e_p[u] = analytic::cor_thornton_ning(speeds_[u], v_y);  // (29)
  return e_p;
}

void Evaluator::combine(std::span<const double> e_a, std::span<const double> e_p, std::span<double> out) const {
  for (std::size_t n = 0; n < out.size(); ++n) {
    const std::size_t u = speed_of_point_[n];
    out[n] = combine_plastic(e_a[u], e_p[u]);
  }
}

void Evaluator::model_cor(const PlasticScales& scales, std::span<const double> e_a, std::optional<double> yield,
                          std::span<double> out) const {
  combine(e_a, plastic_cors(scales, yield), out);
}

double Evaluator::objective(std::span<const double> cor, bool weighted) const {
  return weighted ? weighted_chi2(problem_.data, cor) : mean_squared_residual(problem_.data, cor);
}

}  // namespace detail

double combine_plastic(double cor_adhesive, double cor_plastic) {
  // Below the yield velocity e_P = 1 and (30) is e_A itself (as analysis::collide has it).
  if (cor_plastic >= 1.0 || cor_adhesive == 0.0) return cor_adhesive;
  return analytic::cor_with_plastic(cor_adhesive, cor_plastic);  // K13 (30)
}

double cor_with_yield(const Pair& pair, double velocity, double cor_adhesive, std::optional<double> yield) {
  if (!yield) return cor_adhesive;
  const double v_y = analytic::yield_velocity(pair.effective_radius(), pair.effective_mass(),
                                              pair.effective_modulus(), *yield);  // K13 (28)
  return combine_plastic(cor_adhesive, analytic::cor_thornton_ning(velocity, v_y));  // (29), (30)
}

}  // namespace bounce::analysis

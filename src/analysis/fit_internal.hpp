#pragma once
// Private: what the grid (fit.cpp) and the refinement (fit_refine.cpp) share.

#include <atomic>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bounce/analysis/fit.hpp"

namespace bounce::analysis::detail {

/// The pair's scales that fix the yield velocity K13 (28).
struct PlasticScales {
  double radius = 0.0, mass = 0.0, modulus = 0.0;  ///< R_eff [m], m_eff [kg], E* [Pa]
  bool operator==(const PlasticScales&) const = default;
};
PlasticScales plastic_scales(const Pair& pair);

/// e_A at the data's speeds (each distinct speed integrated once) and e of K13 (30) from it.
class Evaluator {
 public:
  explicit Evaluator(const FitProblem& problem);

  const FitProblem& problem() const { return problem_; }
  const std::vector<double>& speeds() const { return speeds_; }

  /// e_A at every distinct speed for the collision values (several threads over the speeds);
  /// none when a collision fails (NumericalError), its message in `failure`.
  std::optional<std::vector<double>> adhesive(std::span<const double> values, unsigned threads, PlasticScales& scales,
                                              std::string& failure) const;
  /// e_P of K13 (28)-(29) at every distinct speed (1 without a yield strength).
  std::vector<double> plastic_cors(const PlasticScales& scales, std::optional<double> yield) const;
  /// e of K13 (30) at each data point from e_A and e_P at the distinct speeds.
  void combine(std::span<const double> e_a, std::span<const double> e_p, std::span<double> out) const;
  /// Both: e at each data point for the yield strength.
  void model_cor(const PlasticScales& scales, std::span<const double> e_a, std::optional<double> yield,
                 std::span<double> out) const;
  /// K13 (31) or, weighted, the proper chi^2 of model values.
  double objective(std::span<const double> cor, bool weighted) const;

  /// From now on each collision is reported to problem().progress as (collisions so far,
  /// `total`): the grid's count on the grid, 0 after it (the refinement and the ranges, whose
  /// number of collisions is not known in advance).
  void set_progress_total(std::size_t total) const;

  /// Collisions integrated so far.
  std::size_t collisions() const { return collisions_; }
  double collision_seconds() const { return static_cast<double>(collision_nanoseconds_.load()) * 1e-9; }

 private:
  const FitProblem& problem_;
  std::vector<double> speeds_;
  std::vector<std::size_t> speed_of_point_;
  void report_collision() const;
  mutable std::atomic<std::size_t> collisions_{0};
  mutable std::mutex progress_mutex_;
  mutable std::size_t progress_total_ = 0;
  mutable std::atomic<long long> collision_nanoseconds_{0};
};

/// The best yield strength (and its chi^2) for given e_A: the axis's grid, then Brent's
/// method in log Y around the best grid value.
FitMinimum best_yield(const Evaluator& evaluator, const PlasticScales& scales, std::span<const double> e_a,
                      const FitAxis& yield, bool weighted);

/// The grid's minimum refined: Nelder-Mead over the collision axes from `start` (the yield's
/// value comes from best_yield for every trial).
FitMinimum refine(const Evaluator& evaluator, const FitMinimum& start, bool weighted, std::vector<double>& cor_at_best);

/// The range of collision axis `axis` where its profile chi^2 (the other collision axes
/// re-optimised, the yield strength at its best) stays <= threshold around the refined
/// minimum `best`: stepping out from it (a quarter grid step, doubling) and bisecting the
/// crossing; an end is none where the region reaches the grid's edge.
ParameterRange refined_range(const Evaluator& evaluator, const FitMinimum& best, std::size_t axis, double threshold,
                             bool weighted);

/// What the result says about itself (fit_checks.cpp): a best value on the edge of its grid
/// (within the refinement's precision: the optimiser stops that close to a bound it presses
/// on), a parameter whose range spans the whole grid, a yield strength the data do not reach
/// (FitResult::yield_lower_limit), as many parameters as points.
void check_result(const FitProblem& problem, FitResult& result);

}  // namespace bounce::analysis::detail

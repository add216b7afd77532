#pragma once
// A fit's likelihood for Bayesian sampling (bounce.posterior, docs/fitting.md "Posteriors"):
// the inputs of `bounce fit` (the model, the pair, the parameters fitted and their default
// grids) bound once; ln L of many trials at once (analysis/likelihood.hpp).

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "bounce/api/front_door.hpp"

namespace bounce::api {

class Likelihood {
 public:
  /// `inputs` as for fit() (model, pair, fit, grid, threads, ...); refused by its rules.
  Likelihood(const Inputs& inputs, const analysis::Experiment& data);
  /// The fitted parameters: the collision axes, then yield.
  std::vector<std::string> names() const;
  /// Each one's grid [lo, hi] in SI: the fit's (default) range, the prior's default; a yield
  /// strength's ends at most at the theoretical 0.2 E_soft (K13 Fig 7 (b)).
  std::vector<std::array<double, 2>> ranges() const;
  /// ln L of `rows` trials (`values` row-major, names() columns, SI), on the fit's threads
  /// (`threads`: 0 every core).
  std::vector<double> evaluate(std::span<const double> values, std::size_t rows, unsigned threads) const;
  /// Whether the data carry errors (else sigma is marginalised).
  bool weighted() const;

 private:
  FitJob job_;
};

}  // namespace bounce::api

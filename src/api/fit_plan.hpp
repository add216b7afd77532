#pragma once
// Private: a fit's plan (fit_plan.cpp), shared by the front door's fit and its comparison.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "binding.hpp"
#include "bounce/analysis/fit.hpp"

namespace bounce::api::detail {

// What a fit's inputs say: the model, the fitted parameters and their grids, the fixed inputs.
struct Plan {
  std::string model;
  std::vector<ParameterSpec> fitted;  // collision parameters first, yield last
  std::vector<analysis::FitAxis> axes;
  Inputs fixed;   // the user's inputs without the fit command's own
  Bound bound;    // those bound once: a trial sets its values in them (trial_case)
  std::optional<Pair> pair;  // the pair as given (gamma_L, E_soft, the speeds it takes)
  std::optional<double> gamma_l;
  double e_soft = 0.0;
};

/// K13 Fig 7 (b): Y / E_soft reaches the theoretical strength 0.2 at most; the fit's default
/// grid goes on to 1 (where no collision yields), a posterior's prior stops here.
constexpr double theoretical_yield_over_e_soft = 0.2;

/// The plan of bound inputs for `model` (InvalidArgument for a parameter that cannot be
/// fitted, a grid out of its declared range, a fixed value of a fitted parameter).
Plan make_plan(const Bound& bound, const Inputs& inputs, const std::string& model);
/// A trial's case: the bound fixed inputs with the fitted values set (gamma: both bodies'), no
/// text read again.
Case trial_case(const Plan& plan, std::span<const double> values);
/// "a,b,c" split at `separator`.
std::vector<std::string> split(const std::string& text, char separator);

/// The Record of a fit's result (fit_records.cpp): best (a yield strength the data do not
/// determine as null, with lower_limits), ranges, profiles, points, statistics, scales, and
/// with `timing` where the time went.
Record fit_record(const Plan& plan, const analysis::Experiment& data, const analysis::FitResult& f, bool timing);

}  // namespace bounce::api::detail

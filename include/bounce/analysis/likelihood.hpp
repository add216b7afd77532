#pragma once
// The likelihood of a fit's parameters, for Bayesian sampling (docs/fitting.md, "Posteriors"):
// the residuals of K13 (30)-(31) taken as Gaussian measurement errors.

#include <cstddef>
#include <span>
#include <vector>

#include "bounce/analysis/fit.hpp"

namespace bounce::analysis {

/// ln L of one trial, `values` in the problem's order (collision axes, then yield), from the
/// residuals r_i = e_i - e(v_i) of K13 (30)-(31) at the data's N points: with every point's
/// cor_error sigma_i, -(1/2) sum (r_i / sigma_i)^2; without, one unknown sigma marginalised
/// under Jeffreys' prior p(sigma) ~ 1/sigma, -(N/2) ln sum r_i^2 (up to a constant). -inf where
/// a collision of the trial fails numerically (a region the model cannot reach).
double log_likelihood(const FitProblem& problem, std::span<const double> values);

/// ln L of `rows` trials (`values` row-major, one row a trial), the trials on `threads` (0:
/// every core), each trial's collisions on one; bit for bit the same whatever the threads.
std::vector<double> log_likelihoods(const FitProblem& problem, std::span<const double> values, std::size_t rows,
                                    unsigned threads);

}  // namespace bounce::analysis

#pragma once
// Sweeps: one collision per impact speed, and where the outcome changes between them.

#include <cstddef>
#include <functional>
#include <vector>

#include "bounce/analysis/collide.hpp"

namespace bounce::analysis {

/// Called with (done, total) as a long run goes.
using Progress = std::function<void(std::size_t, std::size_t)>;

/// collide() for each velocity; `progress` after each one.
std::vector<dynamics::CollisionOutcome> collide_curve(const Pair& pair, const models::Model& model,
                                                      const std::vector<double>& velocities,
                                                      const CollideOptions& options = {},
                                                      const Progress& progress = {});

/// Where the outcome changes between neighbouring speeds of a sweep.
struct OutcomeBoundary {
  double velocity = 0.0;  ///< [m/s], geometric mean of the final bracket
  dynamics::Outcome below = dynamics::Outcome::stick;
  dynamics::Outcome above = dynamics::Outcome::bounce;
};

/// The change of outcome between speeds lo < hi (outcome `below` at lo, `above` at hi),
/// located by bisection to a relative width `relative_width`.
OutcomeBoundary outcome_boundary(const Pair& pair, const models::Model& model, double lo, double hi,
                                 dynamics::Outcome below, dynamics::Outcome above, const CollideOptions& options = {},
                                 double relative_width = 1e-6);

/// Every change of outcome between neighbours of `velocities` (with their `outcomes`),
/// located by bisection to a relative width `relative_width`.
std::vector<OutcomeBoundary> outcome_boundaries(const Pair& pair, const models::Model& model,
                                                const std::vector<double>& velocities,
                                                const std::vector<dynamics::CollisionOutcome>& outcomes,
                                                const CollideOptions& options = {}, double relative_width = 1e-6);

}  // namespace bounce::analysis

#include "bounce/analysis/curve.hpp"

#include <cmath>

#include "bisect.hpp"

namespace bounce::analysis {

std::vector<dynamics::CollisionOutcome> collide_curve(const Pair& pair, const models::Model& model,
                                                      const std::vector<double>& velocities,
                                                      const CollideOptions& options, const Progress& progress) {
  std::vector<dynamics::CollisionOutcome> out;
  out.reserve(velocities.size());
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    out.push_back(collide(pair, model, velocities[i], options));
    if (progress) progress(i + 1, velocities.size());
  }
  return out;
}

std::vector<OutcomeBoundary> outcome_boundaries(const Pair& pair, const models::Model& model,
                                                const std::vector<double>& velocities,
                                                const std::vector<dynamics::CollisionOutcome>& outcomes,
                                                const CollideOptions& options, double relative_width) {
  std::vector<OutcomeBoundary> out;
  for (std::size_t i = 0; i + 1 < velocities.size(); ++i) {
    const dynamics::Outcome below = outcomes[i].outcome, above = outcomes[i + 1].outcome;
    if (below == above) continue;
    const auto [lo, hi] = detail::bisect_speed(
        velocities[i], velocities[i + 1],
        [&](double v) { return collide(pair, model, v, options).outcome == below; }, relative_width);
    out.push_back({std::sqrt(lo * hi), below, above});
  }
  return out;
}

}  // namespace bounce::analysis

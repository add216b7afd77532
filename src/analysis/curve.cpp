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

OutcomeBoundary outcome_boundary(const Pair& pair, const models::Model& model, double lo, double hi,
                                 dynamics::Outcome below, dynamics::Outcome above, const CollideOptions& options,
                                 double relative_width) {
  const auto bracket = detail::bisect_speed(
      lo, hi, [&](double v) { return collide(pair, model, v, options).outcome == below; }, relative_width);
  return {std::sqrt(bracket.first * bracket.second), below, above};
}

std::vector<OutcomeBoundary> outcome_boundaries(const Pair& pair, const models::Model& model,
                                                const std::vector<double>& velocities,
                                                const std::vector<dynamics::CollisionOutcome>& outcomes,
                                                const CollideOptions& options, double relative_width) {
  std::vector<OutcomeBoundary> out;
  for (std::size_t i = 0; i + 1 < velocities.size(); ++i) {
    const dynamics::Outcome below = outcomes[i].outcome, above = outcomes[i + 1].outcome;
    if (below == above) continue;
    out.push_back(outcome_boundary(pair, model, velocities[i], velocities[i + 1], below, above, options, relative_width));
  }
  return out;
}

}  // namespace bounce::analysis

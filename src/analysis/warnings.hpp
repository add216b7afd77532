#pragma once
// Private: the validity warnings of a collision (BSHP96 appendix B, BP04 (8.26), (8.99),
// K13 §2.1.2 and appendix A, the tangential bound of BSHP96): conditions that do not hold
// are reported with the outcome, never a failure.

#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/model.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::analysis::detail {

void add_warnings(dynamics::CollisionOutcome& out, const Pair& pair, const models::Model& model, double velocity);

}  // namespace bounce::analysis::detail

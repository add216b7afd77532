#pragma once
// Private: BP04 §8.3.4's end of an adhesive collision for its quasi-static estimate
// (adhesive-viscoelastic, Adhesion::weak): the work of breaking the JKR neck, which the force
// (8.56) leaves out (it ends at xi = 0), taken from the rebound.

#include "bounce/dynamics/outcome.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::analysis::detail {

/// BP04 (8.94)-(8.98): a bounce leaves with (1/2) m g''^2 = (1/2) m g'^2 - W0, W0 of (8.95)
/// counted as crack_dissipated; where the rebound's kinetic energy is below W0 the grains stick
/// (8.100), what it held dissipated at the neck.
void add_neck_work(dynamics::CollisionOutcome& out, const Pair& pair);

}  // namespace bounce::analysis::detail

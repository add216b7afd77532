#pragma once
// The front door's `bounce contact resistance` (docs/resistance.md): how a JKR contact resists
// rolling, sliding and twisting, and the energy that breaks it, for any pair of materials.

#include "bounce/api/front_door.hpp"

namespace bounce::api {

/// "contact resistance": the pair (or --materials A[,B]) and xi_crit.
const CommandSpec& resistance_command();

/// Its record: the pair, gamma_s, a0, F_c, delta_c, E_break, and the rolling, sliding and
/// twisting springs, critical displacements, limits and energies (SI units).
Record contact_resistance(const Inputs& inputs);

}  // namespace bounce::api

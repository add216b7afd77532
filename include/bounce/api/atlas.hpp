#pragma once
// The front door's collision atlas (docs/atlas.md): `bounce atlas build|query|export` and
// Python's bounce.atlas, every input checked once by the same rules as the other commands.

#include <string>
#include <vector>

#include "bounce/analysis/atlas.hpp"
#include "bounce/api/front_door.hpp"

namespace bounce::api {

/// "atlas build", "atlas query", "atlas export": the CLI's `bounce atlas WORD`.
const std::vector<CommandSpec>& atlas_commands();
const CommandSpec& atlas_command(std::string_view name);

/// What `atlas build` was asked for: the materials (material[,material2] or materials A,B),
/// the model and its parameters, radius MIN:MAX:N (R_eff), velocity MIN:MAX:N, tol, threads.
analysis::AtlasRequest atlas_request(const Inputs& inputs);

/// The atlas's description: model, parameters, materials, ranges, grid sizes, errors, warnings.
Record atlas_record(const analysis::Atlas& atlas);
/// One lookup (`atlas query`: radius, radius2 or wall, velocity).
Record atlas_query(const analysis::Atlas& atlas, const Inputs& inputs);

}  // namespace bounce::api

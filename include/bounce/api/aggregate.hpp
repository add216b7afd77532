#pragma once
// The front door's aggregates (docs/aggregates.md): `bounce aggregate build` and Python's
// bounce.build_aggregate, every input checked once by the project's rule.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bounce/aggregate/aggregate.hpp"
#include "bounce/api/front_door.hpp"

namespace bounce::api {

/// "aggregate build": the CLI's `bounce aggregate build`.
const std::vector<CommandSpec>& aggregate_commands();

/// What `aggregate build` was asked for: kind, n, radius, seed, the monomers' material (or
/// density), and how many aggregates an ensemble fit of D averages (0: none).
struct AggregateJob {
  aggregate::BuildRequest request;
  std::string material;   ///< "" when --density was given alone
  double density = 0.0;   ///< [kg/m^3], for the data file's masses
  std::size_t ensemble = 0;
};
AggregateJob aggregate_job(const Inputs& inputs);

/// The aggregate's description: the request, its structure (R_g, contacts, coordination,
/// filling factor, smallest distance), its fractal dimension and, with an ensemble, theirs.
Record aggregate_record(const AggregateJob& job, const aggregate::Aggregate& built,
                        const std::optional<aggregate::FractalFit>& ensemble = std::nullopt);

/// The data file's first line: what made it, to build it again.
std::string aggregate_title(const AggregateJob& job);

}  // namespace bounce::api

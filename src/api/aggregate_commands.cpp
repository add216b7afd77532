// The aggregate command's table (docs/aggregates.md): its spec, apart from running it
// (aggregate.cpp), so that the front door's command list does not bring the aggregate code into a
// program that grows none (the browser explorer).
#include "bounce/api/aggregate.hpp"

#include <fmt/format.h>

namespace bounce::api {

namespace {

Range whole(double lo, double hi) { return Range{lo, hi, true, true, false, true}; }

CommandSpec build_command() {
  const double most = static_cast<double>(aggregate::max_monomers);
  return {"aggregate build",
          "Grow a BPCA or BCCA aggregate of equal spheres and write it as a LAMMPS data file",
          false,
          false,
          {choice_parameter("kind", {"bpca", "bcca"},
                            "ballistic particle-cluster (bpca) or cluster-cluster (bcca, n a power of 2) aggregation"),
           real_parameter("n", "number of monomers n", "", whole(1.0, most),
                          fmt::format("number of monomers (1 to {}; bcca: a power of 2)", aggregate::max_monomers)),
           real_parameter("radius", "monomer radius r", "m", positive(), "monomer radius [m]"),
           text_parameter("material", "the monomers' material (its density goes into the data file)", "NAME"),
           real_parameter("density", "monomer density rho", "kg/m^3", positive(),
                          "monomer density [kg/m^3] (default: the material's)"),
           with_default(real_parameter("seed", "random seed", "", whole(0.0, 9007199254740992.0),
                                       "random seed, 0 to 2^53 (the same seed gives the same aggregate everywhere)"),
                        0.0),
           with_default(real_parameter("ensemble", "aggregates in the ensemble fit", "", whole(0.0, 1000.0),
                                       "also fit D over this many aggregates (seeds seed, seed+1, ...; default 0: "
                                       "none)"),
                        0.0)}};
}

}  // namespace

const std::vector<CommandSpec>& aggregate_commands() {
  static const std::vector<CommandSpec> specs = {build_command()};
  return specs;
}

}  // namespace bounce::api

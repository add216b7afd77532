// The atlas commands' table (docs/atlas.md): their specs, apart from running them (atlas.cpp),
// so that the front door's command list does not bring the atlas code into a program.
#include "bounce/api/atlas.hpp"

#include "binding.hpp"
#include "bounce/core/error.hpp"

namespace bounce::api {

namespace {

ParameterSpec range(const char* name, const char* help) { return text_parameter(name, help, "MIN:MAX:N"); }

CommandSpec build_command() {
  CommandSpec c{"atlas build",
                "Tabulate eps, sticking, v_stick, contact time and energy budget over radius and speed (HDF5)",
                true,
                true,
                {range("radius", "reduced radius R_eff [m] MIN:MAX:N (N: the first grid's nodes, 4 to 1024)"),
                 range("velocity", "impact speed [m/s] MIN:MAX:N (N sets the first grid's step in speed, 4 to 1024)"),
                 text_parameter("materials", "body 1's and body 2's materials A[,B] (as --material, --material2)",
                                "A[,B]"),
                 with_default(real_parameter("tol", "tolerance", "", open_interval(1e-7, 0.1),
                                             "largest |eps_atlas - eps_collide| to reach at held-out points (default 1e-4)"),
                              1e-4),
                 with_default(real_parameter("threads", "threads", "", Range{0.0, 1024.0, true, true, false, true},
                                             "worker threads (default 0: every core)"),
                              0.0)}};
  c.unused = {{{detail::tangential_names.begin(), detail::tangential_names.end()},
               "none with atlas build: the atlas tabulates head-on collisions"},
              {{"radius2", "wall", "rigid_wall", "inertia", "inertia2"},
               "none with atlas build: the atlas spans every pair of radii (R2 = inf is a wall of the second "
               "material) and tabulates head-on collisions"}};
  return c;
}

CommandSpec query_command() {
  return {"atlas query",
          "Look up eps, the outcome, v_stick, contact time and energy fractions in an atlas",
          false,
          false,
          {real_parameter("radius", "radius of body 1", "m", positive(), "radius of body 1 [m]"),
           real_parameter("radius2", "radius of body 2", "m", positive(), "radius of body 2 [m] (default: radius)"),
           flag_parameter("wall", "body 2 is a wall of the atlas's second material"),
           real_parameter("velocity", "impact velocity", "m/s", positive(), "impact speed [m/s]"),
           text_parameter("model", "refuse an atlas of another model", "MODEL")}};
}

CommandSpec export_command() {
  return {"atlas export", "Write an atlas's grid as CSV (one row per grid point, SI units)", false, false, {}};
}

}  // namespace

const std::vector<CommandSpec>& atlas_commands() {
  static const std::vector<CommandSpec> specs = {build_command(), query_command(), export_command()};
  return specs;
}

const CommandSpec& atlas_command(std::string_view name) {
  for (const CommandSpec& c : atlas_commands()) {
    if (c.name == name) return c;
  }
  throw InvalidArgument("command", std::string(name), "atlas build, atlas query or atlas export");
}

}  // namespace bounce::api

// The commands' table: each command, its summary and its own parameters (docs/cli.md).
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "binding.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair_parameters.hpp"

namespace bounce::api::detail {

namespace {

ParameterSpec velocity(std::string help) {
  return real_parameter("velocity", "impact velocity", "m/s", positive(), std::move(help));
}

ParameterSpec tangential_velocity() {
  return real_parameter("tangential_velocity", "tangential impact velocity g^T", "m/s", non_negative(),
                        "tangential impact velocity g^T [m/s]: an oblique collision (BSHP96 §II B; 0: head-on)");
}

ParameterSpec range(const char* name, const char* help, const char* placeholder = "LO:HI:N") {
  return text_parameter(name, help, placeholder);
}

ParameterSpec materials_file() {
  for (const ParameterSpec& s : pair_parameters()) {
    if (s.name == "materials_file") return s;
  }
  throw std::logic_error("the pair declares no materials_file");
}

CommandSpec contact_command() {
  return {"contact", "Static contact of two bodies: Hertz, JKR, DMT or Maugis-Dugdale", true, false,
          {with_default(real_parameter("force", "force", "N", Range{}, "total normal force [N] (default 0: zero external load)"),
                        0.0),
           real_parameter("overlap", "overlap", "m", Range{}, "overlap (mutual approach) [m]"),
           range("forces", "CSV curve over forces LO:HI:N [N]"), range("overlaps", "CSV curve over overlaps LO:HI:N [m]"),
           range("contact_radii", "CSV curve over contact radii LO:HI:N [m] (whole curve, both branches)"),
           flag_parameter("log", "geometric spacing of the range")}};
}

CommandSpec collide_command() {
  return {"collide", "One head-on (or oblique) collision: COR, outcome, contact time, energy budget", true, true,
          {velocity("impact velocity g [m/s]"), tangential_velocity(),
           flag_parameter("trajectory", "include the trajectory (direct integration)"),
           // At most 1e5: 1e5 samples take under a second and ~100 MB, 1e6 up to 29 s and 0.7 GB.
           with_default(real_parameter("trajectory_points", "trajectory samples", "", Range{2.0, 1e5, true, true, false, true},
                                       "samples of the trajectory over about one contact time (default 400)"),
                        400.0),
           real_parameter("follow", "follow time", "s", positive(),
                          "models with contact dynamics: keep integrating a sticking collision until this time [s]")}};
}

CommandSpec curve_command() {
  return {"curve", "COR against impact velocity (CSV by default)", true, true,
          {range("velocities", "impact velocities LO:HI:N [m/s]"),
           range("radii", "radii LO:HI:N of body 1 [m] at a fixed velocity (K13 fig. 5)"),
           velocity("the impact velocity of a radii sweep [m/s]"), flag_parameter("log", "geometric spacing of the sweep"),
           flag_parameter("closed_forms", "add K13's e_JKR (24), e_D (26), e_I (27) columns (adhesive models)"),
           tangential_velocity()}};
}

// The tangential law's parameters: a head-on calculation has no use for them.
std::vector<std::string> tangential_parameters() {
  return {detail::tangential_names.begin(), detail::tangential_names.end()};
}

CommandSpec sticking_command() {
  CommandSpec c{"sticking", "The sticking velocity of an adhesive model (and its closed forms)", true, true,
                {range("radii", "radii LO:HI:N of body 1 [m]: CSV of the sticking velocity (K13 fig. 5)"),
                 flag_parameter("log", "geometric spacing of the radii"),
                 with_default(real_parameter("relative_tolerance", "relative tolerance", "", open_interval(1e-12, 0.1),
                                             "relative width of the final bracket (default 1e-6)"),
                              1e-6)}};
  c.unused = {{tangential_parameters(), "none with sticking: the sticking velocity is that of head-on collisions"}};
  c.models = models::model_registry().names_where([](const models::ModelRow& r) { return r.traits.adhesive; });
  c.models_why = fmt::format("an adhesive model ({}): one without adhesion never sticks", fmt::join(c.models, ", "));
  c.model_required = true;
  return c;
}

CommandSpec table_command() {
  return {"table", "eps^N(g) and the outcome, or eps^T(g^N, g^T), as a table for other simulators", true, true,
          {range("velocities", "the table's range LO:HI of (normal) impact speeds [m/s]", "LO:HI"),
           range("tangential_velocities", "a table of eps^T(g^N, g^T) (asperity law) with this range LO:HI of g^T [m/s]",
                 "LO:HI"),
           with_default(real_parameter("bound", "interpolation error bound", "", open_interval(1e-10, 0.1),
                                       "interpolation error to reach (default 1e-6)"),
                        1e-6),
           velocity("with a saved table (--load): the (normal) impact speed at which to read it [m/s]"),
           tangential_velocity()}};
}

CommandSpec analytic_command() {
  CommandSpec c{"analytic", "kappa, g* and the exact COR beside BP04's implicit, series and Pade forms", true, true,
                {velocity("impact velocity g [m/s]")}};
  c.models = models::model_registry().names_where([](const models::ModelRow& r) { return r.traits.analytic; });
  c.models_why = fmt::format("{} (the closed forms of BP04 §8.3 are derived for it)", fmt::join(c.models, ", "));
  c.unused = {{{"contact_end", "yield", "method", "tolerance"},
               "none with analytic: it gives both end rules, without plastic losses"},
              {tangential_parameters(), "none with analytic: BP04's forms are head-on"}};
  return c;
}

CommandSpec fit_command() {
  CommandSpec c{"fit", "Fit a model to a measured restitution curve (K13 §4): best values, ranges, chi^2", true, true,
                {text_parameter("fit", "parameters to fit, P1,P2,... (default: the model's; krijt: gamma,tvis,yield)",
                                "P1,P2"),
                 text_parameter("grid", "grids P=LO:HI:N,... in SI units, log-spaced (default: docs/fitting.md)",
                                "P=LO:HI:N"),
                 flag_parameter("compare", "also fit the comparison models and list chi^2, AIC and BIC (K13 Fig 6)"),
                 with_default(real_parameter("threads", "threads", "", Range{0.0, 1024.0, true, true, false, true},
                                             "worker threads (default 0: every core); the results do not depend on it"),
                              0.0),
                 with_default(real_parameter("precision", "relative precision", "", open_interval(1e-9, 0.1),
                                             "relative precision of the refined parameters (default 1e-3)"),
                              1e-3),
                 flag_parameter("grid_only", "report the grid's minimum, without refining it"),
                 flag_parameter("chi2_grid", "include the whole chi^2 grid (row-major, yield innermost)"),
                 flag_parameter("timing", "include where the time went (grid collisions, e_P, chi^2, refinement)")}};
  const auto& registry = models::model_registry();
  c.models = registry.names_where([](const models::ModelRow& r) { return !r.fit.empty(); });
  c.models_why = "a model with parameters to fit: " + fmt::format("{}", fmt::join(c.models, ", "));
  // K13 §4 fits K13's model: the first line of its comparison of mechanisms (K13 Fig 6).
  for (const auto& row : registry.rows()) {
    for (const auto& k : row.traits.comparisons) {
      if (k.rank == 1) c.default_model = row.name;
    }
  }
  c.unused = {{tangential_parameters(), "none with fit: the restitution data are of head-on collisions"}};
  return c;
}

CommandSpec lammps_command() {
  const auto type = [](const char* name, const char* help) {
    return real_parameter(name, "LAMMPS atom type", "", Range{1.0, 1e6, true, true, false, true}, help);
  };
  CommandSpec c{"lammps", "Stock LAMMPS pair_style granular lines that best represent a model (docs/lammps.md)", true, true,
                {type("type", "the first atom type of the pair_coeff line (default 1)"),
                 type("type2", "the second atom type (default: type for like bodies, else type + 1)")}};
  c.models = models::model_registry().names_where(
      [](const models::ModelRow& r) { return r.traits.stock_lammps != models::StockLammps::none; });
  c.models_why = fmt::format("{} (the models stock LAMMPS has; pair_style bounce has every model)",
                             fmt::join(c.models, ", "));
  c.unused = {{tangential_parameters(), "none with lammps: stock LAMMPS has no BSHP96 asperity law"},
              {{"yield"}, "none with lammps: plastic losses are a post-collision rule, not a LAMMPS contact force"},
              {{"method", "tolerance", "adhesive_tolerance", "curvature_radii", "curvature_radii2", "angle"},
               "none with lammps: LAMMPS integrates spheres with its own time step"},
              {{"wall", "rigid_wall"}, "none with lammps: the lines are for two atom types (docs/lammps.md: walls)"}};
  return c;
}

}  // namespace

std::vector<CommandSpec> make_commands() {
  return {
      {"materials", "List the materials table (K13 table 2 and more)", false, false, {materials_file()}},
      {"models", "List the collision models and contact laws with the parameters each takes", false, false, {}},
      contact_command(),
      collide_command(),
      curve_command(),
      analytic_command(),
      sticking_command(),
      {"rules", "Post-collision velocities and spins (BSHP96 (42)-(43)) of JSON encounters", true, true, {}},
      table_command(),
      fit_command(),
      lammps_command(),
  };
}


}  // namespace bounce::api::detail

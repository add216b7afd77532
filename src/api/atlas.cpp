// The front door's collision atlas (docs/atlas.md).
#include "bounce/api/atlas.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

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

// N: the first grid's nodes (radius) or the step it sets in z (velocity); at most 1024, beyond
// which the refinement's finest grid would be too large to build.
detail::Points atlas_range(const Parameters& own, const char* name, const char* unit) {
  const std::string allowed = fmt::format("MIN:MAX:N with 0 < MIN < MAX in {} and 4 <= N <= 1024", unit);
  if (!own.given(name)) throw InvalidArgument(name, "(not given)", allowed);
  detail::Points p;
  try {
    p = detail::parse_points(name, own.text(name), true);
  } catch (const InvalidArgument&) {
    throw InvalidArgument(name, own.text(name), allowed);
  }
  if (!(p.lo > 0.0) || !(p.hi > p.lo) || p.n < 4 || p.n > 1024) throw InvalidArgument(name, own.text(name), allowed);
  return p;
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

analysis::AtlasRequest atlas_request(const Inputs& typed) {
  if (!typed.count("radius") && !typed.count("velocity")) {  // a first try: what an atlas needs
    throw InvalidArgument("radius", "(not given)",
                          "the ranges of an atlas: --radius MIN:MAX:N (R_eff [m]) and --velocity MIN:MAX:N [m/s], "
                          "with --model, the materials and -o FILE.h5, e.g. `bounce atlas build --model krijt --tvis "
                          "1e-11 --materials water-ice --radius 1e-6:1e-5:4 --velocity 0.3:20:5 -o ice.h5`");
  }
  const detail::Bound b = detail::bind_inputs(atlas_command("atlas build"), detail::with_materials(typed));
  analysis::AtlasRequest r;
  const detail::Points radii = atlas_range(b.own, "radius", "m");
  const detail::Points speeds = atlas_range(b.own, "velocity", "m/s");
  r.radius_min = radii.lo;
  r.radius_max = radii.hi;
  r.radius_nodes = radii.n;
  r.velocity_min = speeds.lo;
  r.velocity_max = speeds.hi;
  r.velocity_nodes = speeds.n;
  r.tolerance = *b.own.real("tol");
  r.threads = static_cast<unsigned>(*b.own.real("threads"));
  r.pair_parameters = b.pair;
  r.model = b.model;
  r.model_parameters = b.model_parameters;
  r.options = analysis::collide_options(b.model_parameters);
  // Every collision of the atlas is valid: its speeds below the sound speed (checked on a
  // pair of the materials; c_t does not depend on the radii).
  const Case probe = detail::make_case(b, radii.lo);
  const double c_t = probe.pair.transversal_sound_speed();
  if (speeds.hi > c_t) {
    throw InvalidArgument("velocity", b.own.text("velocity"),
                          fmt::format("speeds up to the transversal sound speed c_t = {:.4g} m/s, where the "
                                      "quasi-static models end (BSHP96 (B11))", c_t));
  }
  return r;
}

Record atlas_record(const analysis::Atlas& a) {
  Record parameters;
  for (const auto& p : a.parameters) parameters.set(p.name, Record().set("value", p.value).set("unit", p.unit));
  const auto material = [](const Material& m) {
    Record r;
    r.set("name", m.name).set("E", m.youngs_modulus).set("nu", m.poisson_ratio).set("density", m.density);
    if (m.surface_energy) r.set("gamma", *m.surface_energy);
    return r;
  };
  const analysis::AtlasErrors& e = a.errors;
  Record out;
  out.set("model", a.model).set("parameters", parameters).set("body1", material(a.material1));
  out.set("body2", material(a.material2)).set("bounce_version", a.bounce_version);
  out.set("reduced_radius", std::vector<double>{a.radius_min, a.radius_max});
  out.set("velocity", std::vector<double>{a.velocity_min, a.velocity_max});
  out.set("effective_density", std::vector<double>{a.density_min, a.density_max});
  out.set("grid", std::vector<double>{static_cast<double>(a.x.count), static_cast<double>(a.y.count),
                                      static_cast<double>(a.z.count)});
  out.set("errors", Record()
                        .set("cor", e.cor)
                        .set("cor_measured", e.cor_measured)
                        .set("v_stick", e.v_stick)
                        .set("v_stick_measured", e.v_stick_measured)
                        .set("contact_time_measured", e.contact_time)
                        .set("energy_fraction_measured", e.energy)
                        .set("check_points", static_cast<double>(e.check_points))
                        .set("v_stick_points", static_cast<double>(e.v_stick_points))
                        .set("tolerance", e.tolerance));
  out.set("warnings", a.warnings);
  return out;
}

Record atlas_query(const analysis::Atlas& a, const Inputs& inputs) {
  const Parameters own = bind_parameters(atlas_command("atlas query").parameters, inputs, "bounce atlas query");
  if (own.given("model") && own.text("model") != a.model) {
    throw InvalidArgument("model", own.text("model"), fmt::format("the atlas's model, {}", a.model));
  }
  const double r1 = own.require_real("radius", "radius of body 1 [m]");
  if (own.flag("wall") && own.given("radius2")) {
    throw InvalidArgument("radius2", own.typed("radius2"), "none with --wall (a wall has no radius)");
  }
  const double r2 = own.flag("wall") ? std::numeric_limits<double>::infinity() : own.real("radius2").value_or(r1);
  const double v = own.require_real("velocity", "impact speed [m/s]");
  analysis::AtlasValue got;
  try {
    got = a.at({r1, r2, v});
  } catch (const InvalidArgument& e) {
    if (e.parameter() == "radius" || e.parameter() == "radius1") throw InvalidArgument("radius", own.typed("radius") + (own.given("radius2") ? ", --radius2 = " + own.typed("radius2") : ""), e.allowed());
    if (e.parameter() == "velocity") throw InvalidArgument("velocity", own.typed("velocity"), e.allowed());
    throw;
  }
  Record out;
  out.set("cor", got.cor).set("outcome", got.sticks ? "stick" : "bounce");
  if (std::isinf(got.v_stick)) {
    out.set("v_stick", nullptr).set("note", "the grains stick at every speed of the atlas (up to the sound speed)");
  } else {
    out.set("v_stick", got.v_stick);
  }
  out.set("contact_time", got.contact_time ? Value(*got.contact_time) : Value(nullptr));
  out.set("bulk_fraction", got.bulk_fraction ? Value(*got.bulk_fraction) : Value(nullptr));
  out.set("crack_fraction", got.crack_fraction ? Value(*got.crack_fraction) : Value(nullptr));
  out.set("cor_error", a.errors.cor).set("v_stick_error", a.errors.v_stick);
  return out;
}

}  // namespace bounce::api

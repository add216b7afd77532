// The front door's LAMMPS side (docs/lammps.md): pair_coeff and fix wall/bounce, a pair of
// materials and a model by the CLI's names and rules made into a DEM contact law; and
// `bounce lammps`, the stock pair_style granular lines that best represent a model.
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "binding.hpp"
#include "bounce/api/front_door.hpp"
#include "bounce/contact/resistance.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair_parameters.hpp"

namespace bounce::api {

namespace {

// The rolling, sliding and twisting springs of docs/resistance.md: each `yes` or `no`, and xi_crit.
std::vector<ParameterSpec> resistance_parameters() {
  const auto on = [](const char* name, const char* help) {
    return with_default(choice_parameter(name, {"yes", "no"}, help), std::string("no"));
  };
  return {on("rolling", "W07's rolling spring, held at xi_crit (docs/resistance.md): yes or no (default no)"),
          on("sliding", "W07's sliding spring, the contact's tangential force instead of friction: yes or no (default no)"),
          on("twisting", "W07's twisting spring: yes or no (default no)"),
          with_default(real_parameter("xi_crit", "critical rolling displacement", "m", positive(),
                                      "critical rolling displacement xi_crit [m] (default 8e-10, W07's)"),
                       contact::resistance::standard_critical_rolling)};
}

CommandSpec make_pair_coeff_command() {
  CommandSpec c{"pair_coeff", "LAMMPS pair_style bounce: a model as the contact law of one pair of atom types", true,
                true, resistance_parameters()};
  c.models = models::model_registry().names();  // every model has a DEM law (models/model.hpp)
  c.models_why = fmt::format("a model with a DEM law: {}", fmt::join(c.models, ", "));
  c.unused = {
      {{"radius", "radius2", "density", "density2", "inertia", "inertia2"},
       "none in LAMMPS: each atom's radius and mass come from LAMMPS (atom_style sphere), and its moment of "
       "inertia is a solid sphere's"},
      {{"wall", "rigid_wall"}, "none in pair_coeff: pair_style bounce acts between atoms (walls: fix wall/bounce)"},
      {{"yield"},
       "none in LAMMPS: plastic losses (K13 (28)-(30)) are a rule applied after a collision, not a contact force"},
      {{"method", "tolerance", "adhesive_tolerance", "stiff_engine"},
       "none in LAMMPS: its time step integrates the contact"},
      {{"curvature_radii", "curvature_radii2", "angle"}, "none in LAMMPS: its grains are spheres"},
  };
  return c;
}

CommandSpec make_fix_wall_command() {
  CommandSpec c = make_pair_coeff_command();
  c.name = "fix_wall";
  c.summary = "LAMMPS fix wall/bounce: a model as the contact law between atoms and a flat wall";
  // Body 2 is the wall: elastic, of material2 (or E2, nu2, gamma2; default body 1's), or
  // rigid_wall. `wall` itself is implied.
  c.unused[1] = {{"wall"}, "none in fix wall/bounce: its wall is body 2 (material2, E2, nu2, gamma2, or rigid_wall yes)"};
  // A crack law's contact radius is per-contact history, which fix wall/bounce does not keep.
  c.models.clear();
  for (const auto& row : models::model_registry().rows()) {
    if (row.traits.engine != models::Engine::crack) c.models.push_back(row.name);
  }
  c.models_why = fmt::format("a model with a DEM wall law: {} (krijt acts between atoms only, in pair_style bounce)",
                             fmt::join(c.models, ", "));
  return c;
}

}  // namespace

const CommandSpec& fix_wall_command() {
  static const CommandSpec spec = make_fix_wall_command();
  return spec;
}

const CommandSpec& pair_coeff_command() {
  static const CommandSpec spec = make_pair_coeff_command();
  return spec;
}

namespace {
// pair_coeff's rolling, sliding and twisting (resistance_parameters) onto the law.
void add_resistance(models::DemModel& law, const Pair& pair, const Parameters& own, bool wall) {
  const bool rolling = own.text("rolling") == "yes", sliding = own.text("sliding") == "yes",
             twisting = own.text("twisting") == "yes";
  if (own.given("xi_crit") && !rolling) {
    throw InvalidArgument("xi_crit", own.typed("xi_crit"), "rolling yes beside it (xi_crit is the rolling spring's)");
  }
  if (!rolling && !sliding && !twisting) return;
  const char* first = rolling ? "rolling" : sliding ? "sliding" : "twisting";
  if (wall) {
    throw InvalidArgument(first, "yes", "no in fix wall/bounce: a wall contact has no contact pointers (rolling, "
                                        "sliding and twisting act between atoms, in pair_style bounce)");
  }
  if (sliding && law.tangential) {
    throw InvalidArgument("sliding", "yes", "no beside friction: W07's sliding spring is the contact's tangential force "
                                            "(give friction or sliding yes, not both)");
  }
  law.resistance = models::ResistanceModel{contact::resistance::materials_of(pair, first), *own.real("xi_crit"), rolling,
                                           sliding, twisting};
}

// The pair of a DEM law is built for its materials only: a placeholder radius and density stand
// in for the atoms' (each contact gets its own R_eff and m_eff; the command refuses them as
// inputs). The pair's inputs are passed on as typed, so that a message names what the user wrote.
models::DemModel dem_law(const CommandSpec& command, const Inputs& inputs, bool wall) {
  const detail::Bound b = detail::bind_inputs(command, inputs);
  Inputs pair_inputs;
  for (const ParameterSpec& spec : pair_parameters()) {
    if (const auto it = inputs.find(spec.name); it != inputs.end()) pair_inputs.emplace(it->first, it->second);
  }
  pair_inputs["radius"] = 1.0;
  pair_inputs["density"] = 1.0;
  if (wall && !b.pair.flag("rigid_wall")) pair_inputs["wall"] = true;
  const Pair pair = bounce::make_pair(bind_parameters(pair_parameters(), pair_inputs, "the pair"));
  models::DemModel law = models::make_dem_model(pair, b.model, b.model_parameters);
  add_resistance(law, pair, b.own, wall);
  return law;
}
}  // namespace

models::DemModel dem_model(const Inputs& inputs) { return dem_law(pair_coeff_command(), inputs, false); }

models::DemModel wall_dem_model(const Inputs& inputs) { return dem_law(fix_wall_command(), inputs, true); }

// --- bounce lammps: the stock pair_style granular lines that best represent a model ------

namespace {

// The shortest text that reads back as the same double.
std::string exact(double x) { return fmt::format("{}", x); }

struct Export {
  std::vector<std::string> lines;
  std::vector<std::string> notes;
  Record mapping;
};

// The Hertz constant: LAMMPS's hertz/material (and jkr) mix E and nu of the two types as
// bounce does for like types; an I J line carries one E and nu, so it gets E = 2 E* (1 - nu^2).
std::string moduli(const Pair& pair, bool like, Export& out) {
  const Material& m1 = pair.body1().material;
  if (like) return fmt::format("{} {{damping}} {}", exact(m1.youngs_modulus), exact(m1.poisson_ratio));
  const double nu = m1.poisson_ratio;
  out.notes.push_back(fmt::format("unlike materials: E = 2 E* (1 - nu^2) with nu = {} gives LAMMPS's mixing of one "
                                  "E and nu bounce's E* = {} Pa",
                                  format_value(nu), format_value(pair.effective_modulus())));
  return fmt::format("{} {{damping}} {}", exact(2.0 * pair.effective_modulus() * (1.0 - nu * nu)), exact(nu));
}

Export export_lines(const Case& c, long type1, long type2) {
  Export out;
  const Pair& pair = c.pair;
  const models::Model& model = c.model;
  const bool like = pair.body1().material.youngs_modulus == pair.body2().material.youngs_modulus &&
                    pair.body1().material.poisson_ratio == pair.body2().material.poisson_ratio;
  const double a = model.dissipative_constant.value_or(0.0);
  const double m = pair.effective_mass();
  // BSHP96 (24) / K13 (19): F_D = 2 A E* a xi'; LAMMPS's damping viscoelastic is eta_n0 a m_eff v_n.
  const double eta = 2.0 * a * pair.effective_modulus() / m;
  out.mapping.set("E_star", pair.effective_modulus()).set("eta_n0", eta).set("effective_mass", m);
  const std::string head = fmt::format("pair_coeff {} {} ", type1, type2);
  std::string coeff;
  std::string extra;
  // No tangential force (stock LAMMPS has no BSHP96 law). jkr keeps a history all the same:
  // LAMMPS 29Sep2021 stops with "Neighbor history overflow" when a jkr contact outlives a
  // neighbor-list exchange with no history values (linear_nohistory; measured).
  std::string tangential = "tangential linear_nohistory 0 0";
  if (model.traits.stock_lammps == models::StockLammps::jkr) {
    tangential = "tangential linear_history 0 0 0";
    const double w = pair.surface_energy().value_or(0.0);
    out.mapping.set("gamma_lammps", 0.5 * w);
    coeff = "jkr " + moduli(pair, like, out) + " " + exact(0.5 * w);
    out.notes.push_back(fmt::format("jkr: LAMMPS's surface energy is half bounce's work of adhesion: {} = {} / 2 "
                                    "J/m^2 (its force is K13 (9) with w = 2 gamma_LAMMPS)",
                                    format_value(0.5 * w), format_value(w)));
    if (model.end_rule == models::EndRule::pull_off) {
      out.notes.push_back("LAMMPS ends a jkr contact at the pull-off point, as bounce with --contact-end pull-off");
    } else {
      out.notes.push_back("NOT REPRESENTED: bounce ends this contact at the JKR fold (K13 (25)); LAMMPS ends it "
                          "earlier, at the pull-off point: its COR is higher and its sticking velocity lower (as "
                          "bounce --contact-end pull-off; pair_style bounce has both)");
    }
    out.mapping.set("lammps_end", "pull-off");
  } else {
    coeff = "hertz/material " + moduli(pair, like, out);
    const bool force = model.end_rule == models::EndRule::force;
    if (force) extra = " limit_damping";
    out.mapping.set("lammps_end", force ? "force (limit_damping)" : "overlap");
  }
  const std::size_t at = coeff.find("{damping}");
  coeff.replace(at, 9, exact(eta));
  out.lines.push_back(head + coeff + " damping viscoelastic " + tangential + extra);
  if (a > 0.0) {
    out.notes.push_back(fmt::format("eta_n0 = 2 A E* / m_eff = {} 1/s with m_eff = {} kg: exact for this pair's masses "
                                    "only; other sizes in these types get BSHP96's damping times m_eff / {} (pair_style "
                                    "bounce is exact for every size)",
                                    format_value(eta), format_value(m), format_value(m)));
  }
  out.notes.push_back("tangential: none (stock LAMMPS has no BSHP96 asperity law; pair_style bounce has it)");
  return out;
}

}  // namespace

Record lammps_export(const Inputs& inputs) {
  const detail::Bound b = detail::bind_inputs(command("lammps"), inputs);
  const Case c = detail::make_case(b);
  const bool like_bodies = c.pair.body1().material.youngs_modulus == c.pair.body2().material.youngs_modulus &&
                           c.pair.body1().material.poisson_ratio == c.pair.body2().material.poisson_ratio &&
                           c.pair.body1().material.surface_energy == c.pair.body2().material.surface_energy;
  // One atom type is one material: unlike bodies are two types. LAMMPS wants I <= J.
  long type1 = static_cast<long>(b.own.real("type").value_or(1.0));
  long type2 = static_cast<long>(b.own.real("type2").value_or(static_cast<double>(like_bodies ? type1 : type1 + 1)));
  if (!like_bodies && type1 == type2) {
    throw InvalidArgument("type2", b.own.given("type2") ? b.own.typed("type2") : std::to_string(type2),
                          fmt::format("a type other than type = {} for unlike bodies (one atom type, one material)", type1));
  }
  if (type1 > type2) std::swap(type1, type2);
  const Export e = export_lines(c, type1, type2);
  std::string script = fmt::format("# bounce lammps: model {} as stock LAMMPS (pair_style granular, 29Sep2021)\n",
                                   c.model.name);
  for (const std::string& note : e.notes) script += "# " + note + "\n";
  script += "pair_style granular\n";
  for (const std::string& line : e.lines) script += line + "\n";
  Value::List lines(e.lines.begin(), e.lines.end()), notes(e.notes.begin(), e.notes.end());
  Record out;
  out.set("model", c.model.name).set("pair_style", "granular").set("pair_coeff", lines).set("notes", notes);
  out.set("mapping", e.mapping).set("script", script).set("pair", pair_record(c.pair));
  return out;
}

}  // namespace bounce::api

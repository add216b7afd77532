// LAMMPS's pair_coeff as a front-door command: a pair of materials and a model, by the CLI's
// names and checked by its rules, made into a DEM contact law (docs/lammps.md).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "binding.hpp"
#include "bounce/api/front_door.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair_parameters.hpp"

namespace bounce::api {

namespace {

CommandSpec make_pair_coeff_command() {
  CommandSpec c{"pair_coeff", "LAMMPS pair_style bounce: a model as the contact law of one pair of atom types", true,
                true, {}};
  for (const auto& row : models::model_registry().rows()) {
    if (row.contact_law) c.models.push_back(row.name);
  }
  c.models_why = fmt::format("a model with a DEM contact law: {} (krijt's crack law is not a LAMMPS contact law yet)",
                             fmt::join(c.models, ", "));
  c.unused = {
      {{"radius", "radius2", "density", "density2", "inertia", "inertia2"},
       "none in pair_coeff: each atom's radius and mass come from LAMMPS (atom_style sphere), and its moment of "
       "inertia is a solid sphere's"},
      {{"wall", "rigid_wall"}, "none in pair_coeff: pair_style bounce acts between atoms (docs/lammps.md: walls)"},
      {{"yield"},
       "none in LAMMPS: plastic losses (K13 (28)-(30)) are a rule applied after a collision, not a contact force"},
      {{"method", "tolerance", "adhesive_tolerance", "stiff_engine"},
       "none in LAMMPS: its time step integrates the contact"},
      {{"curvature_radii", "curvature_radii2", "angle"}, "none in LAMMPS: its grains are spheres"},
  };
  return c;
}

}  // namespace

const CommandSpec& pair_coeff_command() {
  static const CommandSpec spec = make_pair_coeff_command();
  return spec;
}

models::DemModel contact_law(const Inputs& inputs) {
  const detail::Bound b = detail::bind_inputs(pair_coeff_command(), inputs);
  // The pair is built for its materials only: a placeholder radius and density stand in for
  // the atoms' (each contact gets its own R_eff and m_eff; refused above as inputs).
  Inputs pair_inputs = b.pair.values();
  pair_inputs["radius"] = 1.0;
  pair_inputs["density"] = 1.0;
  const Pair pair = bounce::make_pair(bind_parameters(pair_parameters(), pair_inputs, "the pair"));
  return models::make_contact_law(pair, b.model, b.model_parameters);
}

}  // namespace bounce::api

// The library's results as Records: one serialisation for the CLI's JSON and Python's dicts.
#include <cmath>

#include "bounce/api/front_door.hpp"
#include "bounce/dynamics/outcome.hpp"
#include "records.hpp"

namespace bounce::api {

namespace {

Record body_record(const Body& b) {
  Record r = detail::material_record(b.material, "material");
  if (b.is_wall()) {
    r.set("kind", b.rigid ? "rigid-wall" : "wall");
  } else {
    r.set("kind", "sphere");
    r.set("radius", b.radius);
    r.set("mass", b.mass());
  }
  return r;
}

Record tangential_record(const dynamics::TangentialOutcome& t) {
  Record r = to_record(named_values(t));
  r.set("breaks", t.breaks);
  r.set("steps", t.steps);
  return r;
}

Table trajectory_table(const std::vector<dynamics::TrajectorySample>& samples) {
  Table t;
  t.columns = {"time",    "overlap", "rate",    "contact_radius",  "elastic_force",   "dissipative_force",
               "beta",    "kinetic", "elastic", "surface",         "bulk_dissipated", "crack_dissipated"};
  for (const auto& s : samples) {
    t.rows.push_back({s.time, s.overlap, s.rate, s.contact_radius, s.elastic_force, s.dissipative_force,
                      s.effective_surface_energy_ratio, s.kinetic, s.elastic, s.surface, s.bulk_dissipated,
                      s.crack_dissipated});
  }
  return t;
}

}  // namespace

Record pair_record(const Pair& pair) {
  Record r;
  r.set("body1", body_record(pair.body1()));
  r.set("body2", body_record(pair.body2()));
  r.set("effective_radius", pair.effective_radius());
  r.set("effective_mass", pair.effective_mass());
  r.set("effective_modulus", pair.effective_modulus());
  r.set("hertz_compliance_d", pair.hertz_compliance_d());
  r.set("hertz_constant", pair.hertz_constant());
  r.set("tangential_mass_factor", pair.tangential_mass_factor());
  r.set("surface_energy", pair.surface_energy() ? Value(*pair.surface_energy()) : Value());
  return r;
}

Value detail::contact_time_value(const dynamics::CollisionOutcome& o) {
  return o.outcome == dynamics::Outcome::stick ? Value() : Value(o.contact_time);
}

Value detail::max_overlap_value(const dynamics::CollisionOutcome& o) {
  return o.compression_unfinished ? Value() : Value(o.max_overlap);
}

namespace {

// What the record of sticking grains says about its times and energies (docs/adhesive.md).
constexpr const char* sticking_note =
    "the grains stick, so they have no contact time (contact_time is null): integrated_time is how long the "
    "collision was integrated, and energy.kinetic_at_stop the relative kinetic energy at its end, which the "
    "attraction can raise above initial_kinetic (surface_remaining < 0 holds what it gave)";

// The energy budget by name; for sticking grains the kinetic energy is where the integration
// stopped, not after the collision.
Record energy_record(const dynamics::CollisionOutcome& o) {
  auto values = named_values(o.energy);
  if (o.outcome == dynamics::Outcome::stick) {
    for (auto& [name, value] : values) {
      if (name == "final_kinetic") name = "kinetic_at_stop";
    }
  }
  return to_record(values);
}

}  // namespace

Record outcome_record(const dynamics::CollisionOutcome& o) {
  const bool stuck = o.outcome == dynamics::Outcome::stick;
  Record r;
  r.set("cor", o.cor);
  r.set("outcome", dynamics::to_string(o.outcome));
  r.set("contact_time", detail::contact_time_value(o));
  if (stuck) r.set("integrated_time", o.contact_time);
  r.set("max_overlap", detail::max_overlap_value(o));
  r.set("time_of_max_overlap", o.compression_unfinished ? Value() : Value(o.time_of_max_overlap));
  r.set("method", o.method);
  r.set("steps", o.steps);
  r.set("energy", energy_record(o));
  if (o.tangential) {
    r.set("cor_tangential", o.tangential->cor);
    r.set("tangential", tangential_record(*o.tangential));
  }
  r.set("warnings", o.warnings);
  std::vector<std::string> notes = o.notes;
  if (stuck) notes.insert(notes.begin(), sticking_note);
  r.set("notes", notes);
  if (!o.trajectory.empty()) r.set("trajectory", trajectory_table(o.trajectory));
  return r;
}

}  // namespace bounce::api

// --- what several commands add --------------------------------------------------------

#include "bounce/analysis/closed_forms.hpp"

namespace bounce::api::detail {

Record material_record(const Material& m, const char* name_key) {
  Record j;
  j.set(name_key, m.name);
  j.set("youngs_modulus", m.youngs_modulus);
  j.set("poisson_ratio", m.poisson_ratio);
  j.set("density", m.density);
  j.set("surface_energy", m.surface_energy ? Value(*m.surface_energy) : Value());
  return j;
}

void add_scales(Record& out, const Pair& pair, const models::Model& model, double velocity) {
  if (!model.hertz) return;
  const analysis::ViscoelasticScales s = analysis::viscoelastic_scales(pair, model, velocity);
  out.set("dissipative_constant", s.dissipative_constant);
  out.set("force_constant", s.force_constant);
  out.set("kappa", s.kappa);
  if (std::isfinite(s.characteristic_velocity)) out.set("characteristic_velocity", s.characteristic_velocity);
  out.set("reference_overlap", s.reference_overlap);
  out.set("hertz_contact_time", s.hertz_contact_time);
}

// A closed form beyond its validity is null, with the warning saying why (absent otherwise).
Record closed_forms_record(const Pair& pair, const models::Model& model, double velocity) {
  const analysis::ClosedForms forms = analysis::closed_forms(pair, model, velocity);
  Record r;
  for (const auto& [key, value] : analysis::named_values(forms)) r.set(key, value ? Value(*value) : Value());
  if (!forms.warnings.empty()) r.set("warnings", forms.warnings);
  return r;
}

Record merged_record(const Pair& pair, double velocity) {
  const analysis::MergedBody m = analysis::merged_body(pair, velocity);
  return Record()
      .set("mass", std::isfinite(m.mass) ? Value(m.mass) : Value("wall"))
      .set("velocity", m.velocity)
      .set("frame", "body 2 at rest before the impact");
}

}  // namespace bounce::api::detail

// The front door's listings: the materials table and the registries of models and laws.
#include <string>

#include "binding.hpp"
#include "records.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/materials_table.hpp"

namespace bounce::api {

namespace {

Record table_entry(const Material& m) {
  Record j = detail::material_record(m);
  if (m.surface_energy_range) {
    j.set("surface_energy_range", std::vector<double>{(*m.surface_energy_range)[0], (*m.surface_energy_range)[1]});
  }
  j.set("source", m.source);
  return j;
}

const char* kind_name(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::real: return "real";
    case ParameterKind::reals: return "reals";
    case ParameterKind::choice: return "choice";
    case ParameterKind::text: return "text";
    case ParameterKind::flag: return "flag";
  }
  return "";
}

Record parameter_record(const ParameterSpec& s) {
  Record r;
  r.set("name", s.name);
  r.set("kind", kind_name(s.kind));
  r.set("unit", s.unit);
  r.set("help", s.help);
  if (s.kind == ParameterKind::real || s.kind == ParameterKind::reals) r.set("allowed", s.range.describe(s.what()));
  if (s.kind == ParameterKind::choice) r.set("choices", s.choices);
  r.set("default", s.default_value ? Value(s.default_text()) : Value());
  return r;
}

Value parameters_value(const std::vector<ParameterSpec>& specs) {
  Value::List out;
  for (const ParameterSpec& s : specs) out.push_back(parameter_record(s));
  return out;
}

std::string engine_name(models::Engine e) {
  switch (e) {
    case models::Engine::force_law: return "force law";
    case models::Engine::adhesive: return "adhesive contact";
    case models::Engine::crack: return "crack";
  }
  return "";
}

std::string adhesion_name(models::Adhesion a) {
  switch (a) {
    case models::Adhesion::unchecked: return "unchecked";
    case models::Adhesion::negligible: return "negligible";
    case models::Adhesion::weak: return "weak";
    case models::Adhesion::jkr: return "jkr";
    case models::Adhesion::maugis: return "maugis-dugdale";
  }
  return "";
}

// What a row declares about its model (models::Traits), and which DEM law it has (every model
// has one: a crack law's where its engine is the crack's).
Record traits_record(const models::ModelRow& row) {
  const models::Traits& t = row.traits;
  Value::List rules;
  for (models::EndRule r : t.end_rules) rules.emplace_back(std::string(models::to_string(r)));
  const char* dem = t.engine == models::Engine::crack ? "contact radius of its own" : "force";
  return Record()
      .set("engine", engine_name(t.engine))
      .set("end_rules", rules)
      .set("adhesion", adhesion_name(t.adhesion))
      .set("adhesive", t.adhesive)
      .set("master_curve", t.master_curve)
      .set("convex", t.convex)
      .set("dem_law", dem)
      .set("docs", "docs/" + t.docs);
}

}  // namespace

Value materials(const Inputs& inputs) {
  const Parameters p = bind_parameters(command("materials").parameters, inputs, "bounce materials");
  const MaterialTable table =
      p.given("materials_file") ? MaterialTable::builtin().with(MaterialTable::from_file(p.text("materials_file")))
                                : MaterialTable::builtin();
  Value::List out;
  for (const Material& m : table.materials()) out.push_back(table_entry(m));
  return out;
}

Value models() {
  Value::List model_list, law_list;
  for (const auto& row : models::model_registry().rows()) {
    model_list.push_back(Record()
                             .set("name", row.name)
                             .set("summary", row.summary)
                             .set("references", row.references)
                             .set("traits", traits_record(row))
                             .set("parameters", parameters_value(row.parameters)));
  }
  for (const auto& row : contact::contact_laws()) {
    law_list.push_back(Record()
                           .set("name", row.name)
                           .set("summary", row.summary)
                           .set("references", row.references)
                           .set("needs_surface_energy", row.needs_surface_energy)
                           .set("parameters", parameters_value(row.parameters)));
  }
  return Record().set("models", std::move(model_list)).set("laws", std::move(law_list));
}

}  // namespace bounce::api

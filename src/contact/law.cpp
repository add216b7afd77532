#include "bounce/contact/law.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bounce/contact/surface_forces.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::contact {

std::vector<std::pair<std::string, double>> named_values(const AdhesionSummary& a) {
  return {{"pull_off_force", a.pull_off_force},
          {"pull_off_contact_radius", a.pull_off_contact_radius},
          {"zero_load_contact_radius", a.zero_load_contact_radius},
          {"zero_load_overlap", a.zero_load_overlap},
          {"separation_overlap", a.separation_overlap},
          {"separation_contact_radius", a.separation_contact_radius}};
}

namespace {

std::vector<ParameterSpec> hertz_parameters() {
  const auto shape = convex::shape_parameters();
  return {shape.begin(), shape.end()};
}

std::unique_ptr<ContactLaw> hertz_law(const Pair& pair, const Parameters& p) {
  const auto shape = convex::curvatures_from(p, pair.body2().is_wall());
  return shape ? make_convex_hertz_law(pair, *shape) : make_hertz_law(pair);
}

// The table: one row per law (keyword, needs gamma, summary, references, parameters, factory).
std::vector<LawRow> rows() {
  return {
      {"hertz", false, "elastic, non-adhesive spheres (or convex bodies with curvature radii)",
       "BP04 (8.23)-(8.24), (8.6)-(8.21), K13 (4)-(5)", hertz_parameters(), &hertz_law},
      {"jkr", true, "adhesion inside the contact (large, soft, sticky spheres)", "K13 (6)-(10), BP04 (8.46)-(8.52)",
       {surface::z0_parameter()}, [](const Pair& pair, const Parameters&) { return make_jkr_law(pair); }},
      {"dmt", true, "Hertz profile plus adhesion outside the contact (small, hard spheres)", "BP04 after (8.52)",
       {surface::z0_parameter()}, [](const Pair& pair, const Parameters&) { return make_dmt_law(pair); }},
      {"maugis", true, "Dugdale cohesive zone; JKR-DMT transition via lambda = 1.157 mu",
       "Maugis (1992), BP04 ref. [19]", {surface::z0_parameter()},
       [](const Pair& pair, const Parameters& p) { return make_maugis_law(pair, *p.real("z0")); }},
  };
}

}  // namespace

const std::vector<LawRow>& contact_laws() {
  static const std::vector<LawRow> table = rows();
  return table;
}

const LawRow& contact_law(std::string_view name) { return find_named(contact_laws(), name, "law"); }

std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const Pair& pair, const Parameters& p) {
  return contact_law(name).factory(pair, p);
}

std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const Pair& pair, const ParameterInputs& inputs) {
  const LawRow& row = contact_law(name);
  return row.factory(pair, bind_parameters(row.parameters, inputs, fmt::format("law {}", row.name)));
}

}  // namespace bounce::contact

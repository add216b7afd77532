#include "bounce/contact/law.hpp"

#include <fmt/format.h>

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

const std::vector<LawInfo>& contact_laws() {
  static const std::vector<LawInfo> table = {
      {"hertz", false, "elastic, non-adhesive spheres", "BP04 (8.23)-(8.24), K13 (4)-(5)"},
      {"jkr", true, "adhesion inside the contact (large, soft, sticky spheres)",
       "K13 (6)-(10), BP04 (8.46)-(8.52)"},
      {"dmt", true, "Hertz profile plus adhesion outside the contact (small, hard spheres)",
       "BP04 after (8.52)"},
      {"maugis", true, "Dugdale cohesive zone; JKR-DMT transition via lambda = 1.157 mu",
       "Maugis (1992), BP04 ref. [19]"},
  };
  return table;
}

std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const Pair& pair,
                                             const LawOptions& options) {
  if (name == "hertz") return make_hertz_law(pair);
  if (name == "jkr") return make_jkr_law(pair);
  if (name == "dmt") return make_dmt_law(pair);
  if (name == "maugis") {
    require_positive("z0", options.z0, "equilibrium separation z0 [m]");
    return make_maugis_law(pair, options.z0);
  }
  std::vector<std::string> names;
  for (const LawInfo& info : contact_laws()) names.push_back(info.name);
  throw InvalidArgument("law", std::string(name), fmt::format("one of {}", fmt::join(names, ", ")));
}

}  // namespace bounce::contact

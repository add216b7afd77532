/* Type pairs' laws in pair_style bounce (type_laws.h). */

#include "type_laws.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "bounce/api/front_door.hpp"

namespace bounce::lammps {

namespace {

// A body's material keys and body 2's names for them (bounce's pair parameters).
constexpr std::array<std::pair<const char*, const char*>, 5> body_keys{
    {{"material", "material2"}, {"E", "E2"}, {"nu", "nu2"}, {"gamma", "gamma2"}, {"surface_energy", "surface_energy2"}}};

bool is_body_key(const std::string& key) {
  for (const auto& [one, two] : body_keys)
    if (key == one || key == two) return true;
  return false;
}

// The coefficients less the body keys: what two types must share to be mixed.
Coeffs model_keys(const Coeffs& c) {
  Coeffs out;
  for (const auto& [key, value] : c)
    if (!is_body_key(key)) out.emplace(key, value);
  return out;
}

std::string given(const Coeffs& c, const std::string& key) {
  const auto it = c.find(key);
  return it == c.end() ? "(not given)" : it->second;
}

// Two values as typed are the same where their text is, or where both read whole as the same
// number (`tvis 1e-11` and `tvis 1.0e-11`).
bool same(const std::string& a, const std::string& b) {
  if (a == b) return true;
  double x = 0.0, y = 0.0;
  const auto rx = std::from_chars(a.data(), a.data() + a.size(), x);
  const auto ry = std::from_chars(b.data(), b.data() + b.size(), y);
  return rx.ec == std::errc() && ry.ec == std::errc() && rx.ptr == a.data() + a.size() &&
         ry.ptr == b.data() + b.size() && x == y;
}

// The first key whose values differ between the two, the model's first ("" where none does).
std::string first_difference(const Coeffs& a, const Coeffs& b) {
  if (!same(given(a, "model"), given(b, "model"))) return "model";
  for (const auto& [k, v] : a)
    if (!same(given(b, k), v)) return k;
  for (const auto& [k, v] : b)
    if (!same(given(a, k), v)) return k;
  return "";
}

}  // namespace

bool takes_default_asperity_form(const models::DemModel& law, bool form_named) {
  return !form_named && law.tangential && law.tangential->law == models::TangentialLaw::asperity;
}

std::shared_ptr<const TypeLaw> make_type_law(const Coeffs& coeffs) {
  auto entry = std::make_shared<TypeLaw>();
  entry->coeffs = coeffs;
  api::Inputs inputs;
  for (const auto& [key, value] : coeffs) inputs[key] = value;
  entry->law = api::dem_model(inputs);
  if (takes_default_asperity_form(entry->law, coeffs.count("asperity_form") > 0))
    entry->coeffs["asperity_form"] = std::string(models::to_string(entry->law.tangential->form));
  const models::ContactGeometry unit{1.0, 1.0};
  entry->beyond = entry->law.release_overlap(unit) < 0.0;
  entry->snaps = entry->law.snap_overlap(unit) < 0.0;
  return entry;
}

std::shared_ptr<const TypeLaw> mix(const TypeLaw& ii, const TypeLaw& jj, int i, int j) {
  const Coeffs a = model_keys(ii.coeffs), b = model_keys(jj.coeffs);
  if (const std::string key = first_difference(a, b); !key.empty()) {
    throw CannotMix(fmt::format(
        "types {} and {} cannot be mixed: {} = {} for {} {} but {} for {} {} (bounce mixes two types' materials, "
        "not their models' parameters): give pair_coeff {} {}",
        i, j, key, given(ii.coeffs, key), i, i, given(jj.coeffs, key), j, j, std::min(i, j), std::max(i, j)));
  }
  if (ii.coeffs == jj.coeffs) return std::make_shared<TypeLaw>(ii);
  // Body 2 falls back on body 1's material where it has none of its own (make_pair), so that a type
  // J given by E and nu alone takes I's surface energy: harmless, since J's own law, valid without
  // one, has a model that uses none (an adhesive model refuses a pair without gamma).
  Coeffs mixed = ii.coeffs;
  for (const auto& [one, two] : body_keys)
    if (const auto it = jj.coeffs.find(one); it != jj.coeffs.end()) mixed[two] = it->second;
  return make_type_law(mixed);
}

std::shared_ptr<const TypeLaw> restart_type_law(const Coeffs& coeffs, bool& kept_published) {
  kept_published = false;
  auto law = make_type_law(coeffs);
  if (coeffs.count("asperity_form") || !law->coeffs.count("asperity_form")) return law;
  Coeffs before = coeffs;
  before["asperity_form"] = form_before_passive_default;
  kept_published = true;
  return make_type_law(before);
}

std::string to_text(const Coeffs& coeffs) {
  std::string out;
  for (const auto& [key, value] : coeffs) out += (out.empty() ? "" : " ") + key + "=" + value;
  return out;
}

Coeffs from_text(const std::string& text) {
  Coeffs out;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    const auto at = word.find('=');
    if (at == std::string::npos) throw std::invalid_argument("pair_style bounce: a restart's coefficient '" + word + "'");
    out[word.substr(0, at)] = word.substr(at + 1);
  }
  return out;
}

}  // namespace bounce::lammps

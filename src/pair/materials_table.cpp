#include "bounce/pair/materials_table.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce {

// Defined in the generated materials_data.cpp: the text of data/materials.toml.
extern const char* const builtin_materials_toml;

namespace {

const std::set<std::string, std::less<>> known_keys = {
    "name", "youngs_modulus", "poisson_ratio", "density", "surface_energy",
    "surface_energy_range", "source"};

std::string join(const std::vector<std::string>& items) {
  return fmt::format("{}", fmt::join(items, ", "));
}

// Name of a field as the user wrote it in the file, for error messages.
std::string file_key(std::string_view field) {
  if (field == "E") return "youngs_modulus";
  if (field == "nu") return "poisson_ratio";
  if (field == "gamma") return "surface_energy";
  return std::string(field);
}

double required_number(const toml::table& entry, std::string_view key, const std::string& where) {
  const toml::node* node = entry.get(key);
  if (node == nullptr) {
    throw InvalidArgument(where + "." + std::string(key), "(missing)",
                          "a number (every material needs name, youngs_modulus, "
                          "poisson_ratio, density)");
  }
  if (auto v = node->value<double>()) return *v;
  throw InvalidArgument(where + "." + std::string(key), "(not a number)", "a number");
}

Material parse_entry(const toml::table& entry, const std::string& origin, std::size_t index) {
  std::string where = fmt::format("{}: material #{}", origin, index + 1);
  const toml::node* name_node = entry.get("name");
  if (name_node == nullptr || !name_node->is_string()) {
    throw InvalidArgument(where + ".name", "(missing)", "a string naming the material");
  }
  Material m;
  m.name = *name_node->value<std::string>();
  if (m.name.empty()) throw InvalidArgument(where + ".name", "\"\"", "a non-empty name");
  where = fmt::format("{}: {}", origin, m.name);

  for (const auto& [key, node] : entry) {
    if (!known_keys.contains(key.str())) {
      std::vector<std::string> keys(known_keys.begin(), known_keys.end());
      throw InvalidArgument(where + "." + std::string(key.str()), "(unknown key)",
                            "one of " + join(keys));
    }
  }
  m.youngs_modulus = required_number(entry, "youngs_modulus", where);
  m.poisson_ratio = required_number(entry, "poisson_ratio", where);
  m.density = required_number(entry, "density", where);
  if (entry.contains("surface_energy")) {
    m.surface_energy = required_number(entry, "surface_energy", where);
  }
  if (entry.contains("surface_energy") && entry.contains("surface_energy_range")) {
    throw InvalidArgument(where + ".surface_energy_range", "(given with surface_energy)",
                          "surface_energy or surface_energy_range, not both (a range means the value is not known)");
  }
  if (const toml::node* range = entry.get("surface_energy_range")) {
    const toml::array* arr = range->as_array();
    if (arr == nullptr || arr->size() != 2 || !(*arr)[0].value<double>() ||
        !(*arr)[1].value<double>()) {
      throw InvalidArgument(where + ".surface_energy_range", "(malformed)",
                            "two numbers [lo, hi] with 0 <= lo <= hi");
    }
    const double lo = *(*arr)[0].value<double>();
    const double hi = *(*arr)[1].value<double>();
    if (!(lo >= 0.0 && lo <= hi && hi < 1e300)) {
      throw InvalidArgument(where + ".surface_energy_range", fmt::format("[{}, {}]", lo, hi),
                            "two numbers [lo, hi] with 0 <= lo <= hi");
    }
    m.surface_energy_range = std::array<double, 2>{lo, hi};
  }
  if (const toml::node* source = entry.get("source")) {
    if (!source->is_string()) throw InvalidArgument(where + ".source", "(not a string)", "a string");
    m.source = *source->value<std::string>();
  }
  validate(m, [&](std::string_view field) { return where + "." + file_key(field); });
  return m;
}

}  // namespace

MaterialTable MaterialTable::from_toml(std::string_view text, std::string_view origin_view) {
  const std::string origin(origin_view);
  toml::table root;
  try {
    root = toml::parse(text, origin_view);
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    throw InvalidArgument(fmt::format("{}:{}:{}", origin, begin.line, begin.column),
                          "(malformed TOML)", std::string(e.description()));
  }
  for (const auto& [key, node] : root) {
    if (key.str() != "material") {
      throw InvalidArgument(fmt::format("{}: {}", origin, key.str()), "(unknown top-level key)",
                            "only [[material]] entries");
    }
  }
  const toml::array* entries = root["material"].as_array();
  if (entries == nullptr || entries->empty()) {
    throw InvalidArgument(origin, "(no [[material]] entries)", "at least one [[material]] table");
  }
  MaterialTable table;
  for (std::size_t i = 0; i < entries->size(); ++i) {
    const toml::table* entry = (*entries)[i].as_table();
    if (entry == nullptr) {
      throw InvalidArgument(fmt::format("{}: material #{}", origin, i + 1), "(not a table)",
                            "a [[material]] table");
    }
    Material m = parse_entry(*entry, origin, i);
    if (table.contains(m.name)) {
      throw InvalidArgument(fmt::format("{}: {}", origin, m.name), "(duplicate)",
                            "each material name once");
    }
    table.materials_.push_back(std::move(m));
  }
  return table;
}

MaterialTable MaterialTable::from_file(const std::filesystem::path& path) {
  return from_toml(read_text_file("materials_file", path.string(), "a readable TOML file"), path.string());
}

const MaterialTable& MaterialTable::builtin() {
  static const MaterialTable table = from_toml(builtin_materials_toml, "built-in materials.toml");
  return table;
}

bool MaterialTable::contains(std::string_view name) const {
  return std::any_of(materials_.begin(), materials_.end(),
                     [&](const Material& m) { return m.name == name; });
}

const Material& MaterialTable::at(std::string_view name) const {
  for (const Material& m : materials_) {
    if (m.name == name) return m;
  }
  throw InvalidArgument("material", std::string(name), "one of " + join(names()) + did_you_mean(name, names()));
}

MaterialTable MaterialTable::with(const MaterialTable& user) const {
  MaterialTable out = *this;
  for (const Material& m : user.materials_) {
    auto same = std::find_if(out.materials_.begin(), out.materials_.end(), [&](const Material& o) { return o.name == m.name; });
    if (same != out.materials_.end()) *same = m;
    else out.materials_.push_back(m);
  }
  return out;
}

std::vector<std::string> MaterialTable::names() const {
  std::vector<std::string> out;
  out.reserve(materials_.size());
  for (const Material& m : materials_) out.push_back(m.name);
  return out;
}

}  // namespace bounce

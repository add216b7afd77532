// Fuzz target: the materials TOML loader (MaterialTable::from_toml, `--materials-file`).
//
// Input: the text of a materials file. Properties (docs/hardening.md):
//  * from_toml returns or throws InvalidArgument (nothing else: the CLI would exit 4);
//  * a table it accepts holds only valid materials (validate() agrees), each named once and
//    not empty, with 0 <= lo <= hi for a surface-energy range;
//  * the CLI reads the same file: `bounce materials --materials-file F --json` succeeds, and
//    a contact of the first material keeps the CLI's contract (exit 0, 2 or 3, no nan/inf).
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>

#include "bounce/pair/materials_table.hpp"
#include "oracle.hpp"

using bounce::fuzz::finding;

namespace {

void check_accepted(const bounce::MaterialTable& table) {
  std::set<std::string> names;
  for (const bounce::Material& m : table.materials()) {
    if (m.name.empty()) finding("an accepted material has no name");
    if (!names.insert(m.name).second) finding("material " + m.name + " accepted twice");
    if (!table.contains(m.name) || &table.at(m.name) != &m) finding("at(" + m.name + ") is not the material listed");
    if (!bounce::fuzz::only_bounce_errors("validate", [&] { bounce::validate(m); })) {
      finding("material " + m.name + " accepted by from_toml but refused by validate()");
    }
    if (const auto& r = m.surface_energy_range) {
      if (!((*r)[0] >= 0.0 && (*r)[0] <= (*r)[1] && std::isfinite((*r)[1]))) {
        finding("material " + m.name + " accepted with a surface energy range outside 0 <= lo <= hi");
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<bounce::MaterialTable> table;
  if (!bounce::fuzz::only_bounce_errors("MaterialTable::from_toml",
                                        [&] { table = bounce::MaterialTable::from_toml(text, "fuzz.toml"); })) {
    return 0;
  }
  check_accepted(*table);

  const std::string path = bounce::fuzz::scratch_file("materials.toml", text);
  const std::vector<std::string> list = {"materials", "--materials-file", path, "--json"};
  const auto listed = bounce::fuzz::run_cli(list);
  bounce::fuzz::check_cli(list, listed, text);
  if (listed.code != 0) finding("`bounce materials` refuses a file that from_toml accepts:\n" + listed.err);

  const std::string& name = table->materials().front().name;
  const std::vector<std::string> contact = {"contact", "--materials-file", path, "--material=" + name, "--radius", "1e-6",
                                            "--law", table->materials().front().surface_energy ? "jkr" : "hertz"};
  bounce::fuzz::check_cli(contact, bounce::fuzz::run_cli(contact), text);
  return 0;
}

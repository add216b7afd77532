// `bounce materials [--json] [--materials-file F]`: list the materials table.
#include <iostream>

#include <fmt/format.h>

#include "cli.hpp"
#include "commands.hpp"

namespace bounce::cli {

Command add_materials_command(CLI::App& root) {
  auto* app = root.add_subcommand("materials", "List the materials table (K13 table 2 and more)");
  struct State {
    bool json = false;
    std::string file;
  };
  auto state = std::make_shared<State>();
  app->add_flag("--json", state->json, "print JSON");
  app->add_option("--materials-file", state->file, "TOML table to list instead of the built-in one");
  return {app, [state]() {
            const MaterialTable table =
                state->file.empty() ? MaterialTable::builtin() : MaterialTable::from_file(state->file);
            if (state->json) {
              nlohmann::json out = nlohmann::json::array();
              for (const Material& m : table.materials()) {
                nlohmann::json j;
                j["name"] = m.name;
                j["youngs_modulus"] = m.youngs_modulus;
                j["poisson_ratio"] = m.poisson_ratio;
                j["density"] = m.density;
                j["surface_energy"] =
                    m.surface_energy ? nlohmann::json(*m.surface_energy) : nlohmann::json(nullptr);
                if (m.surface_energy_range) {
                  j["surface_energy_range"] = {(*m.surface_energy_range)[0],
                                               (*m.surface_energy_range)[1]};
                }
                j["source"] = m.source;
                out.push_back(j);
              }
              print_json(out);
              return 0;
            }
            std::cout << fmt::format("{:<16} {:>10} {:>6} {:>8} {:>11}  {}\n", "name", "E [GPa]",
                                     "nu", "rho", "gamma", "source");
            std::cout << fmt::format("{:<16} {:>10} {:>6} {:>8} {:>11}\n", "", "", "",
                                     "[kg/m^3]", "[J/m^2]");
            for (const Material& m : table.materials()) {
              std::string gamma = "-";
              if (m.surface_energy) gamma = fmt::format("{:g}", *m.surface_energy);
              if (m.surface_energy_range) {
                gamma = fmt::format("{:g}-{:g}", (*m.surface_energy_range)[0],
                                    (*m.surface_energy_range)[1]);
              }
              std::cout << fmt::format("{:<16} {:>10g} {:>6g} {:>8g} {:>11}  {}\n", m.name,
                                       m.youngs_modulus / 1e9, m.poisson_ratio, m.density, gamma,
                                       m.source);
            }
            return 0;
          }};
}

}  // namespace bounce::cli

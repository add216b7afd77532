// The commands' first steps (first_steps.hpp).

#include "first_steps.hpp"

#include <map>
#include <string>

namespace bounce::cli {

namespace {

using Steps = std::map<std::string_view, FirstSteps>;

// The commands of one word.
Steps command_steps() {
  return {
      {"materials", {"", {"bounce materials", "bounce materials --json"}}},
      {"models", {"", {"bounce models", "bounce models --json"}}},
      {"contact",
       {"the bodies (--material NAME, or --E, --nu), --radius and a contact law (--law, default hertz)",
        {"bounce contact --material water-ice --radius 1e-6 --law jkr",
         "bounce contact --material steel --radius 1e-3 --rigid-wall --force 10 --json"}}},
      {"collide",
       {"the bodies (--material NAME, or --E, --nu and --density), --radius and --velocity",
        {"bounce collide --material water-ice --radius 1e-6 --model krijt --tvis 1e-11 --velocity 3",
         "bounce collide --material ice-bshp96 --radius 0.01 --A 1e-6 --velocity 1 --json",
         "bounce collide --material ice-bshp96 --radius 0.01 --A 1e-6 --velocity 1 --tangential-velocity 0.01 "
         "--friction 0.014142 --asperity 1e-6"}}},
      {"curve",
       {"the bodies (--material NAME, or --E, --nu and --density), --radius and --velocities LO:HI:N",
        {"bounce curve --material water-ice --radius 1e-6 --model krijt --tvis 1e-11 --velocities 0.3:30:7 --log --csv",
         "bounce curve --material ice-bshp96 --radius 0.01 --A 1e-6 --velocities 0.01:1:3 --log --json"}}},
      {"analytic",
       {"the bodies (--material NAME, or --E, --nu and --density), --radius, --A and --velocity",
        {"bounce analytic --material ice-bshp96 --radius 0.01 --wall --A 1e-6 --velocity 1"}}},
      {"sticking",
       {"the bodies (--material NAME, or --E, --nu, --density and --gamma), --radius (or --radii) and an adhesive "
        "--model",
        {"bounce sticking --material water-ice --radius 1e-6 --model krijt --tvis 1e-11",
         "bounce sticking --material water-ice --model krijt --tvis 1e-11 --radii 1e-7:1e-4:4 --log"}}},
      {"rules",
       {"the bodies (--material NAME, or --E, --nu and --density), --radius, and encounters as JSON on stdin",
        {"echo '{\"normal\": [1, 0, 0], \"grain1\": {\"velocity\": [-1, 0.1, 0], \"angular_velocity\": [0, 0, 0]}, "
         "\"grain2\": {\"velocity\": [0, 0, 0], \"angular_velocity\": [0, 0, 0]}}' | bounce rules --material "
         "ice-bshp96 --radius 0.01 --A 1e-6 --friction 0.014142 --asperity 1e-6"}}},
      {"table",
       {"the bodies (--material NAME, or --E, --nu and --density), --radius, --velocities LO:HI and an output "
        "(--json, --csv, --c-header PREFIX)",
        {"bounce table --material water-ice --radius 1e-6 --model krijt --tvis 1e-11 --velocities 0.5:20 --csv"}}},
      {"fit",
       {"--data FILE (a CSV of velocity and cor), the bodies and --radius, and a --model",
        {"printf 'velocity,cor\\n0.05,0.975\\n0.2,0.966\\n0.6,0.951\\n1.3,0.927\\n2,0.905\\n3,0.874\\n' | bounce fit "
         "--data - --material steel --radius 0.5e-3 --wall --material2 ag-coated-glass --model viscoelastic --fit A"}}},
      {"lammps",
       {"the bodies (--material NAME, or --E, --nu and --density), --radius and the model's parameters",
        {"bounce lammps --material ice-bshp96 --radius 0.01 --A 1e-5"}}},
      {"completion", {"", {"bounce completion > bounce.bash"}}},
  };
}

// The commands of two words: `contact resistance`, `atlas build` and its kin, `aggregate build`.
Steps subcommand_steps() {
  return {
      {"contact resistance",
       {"the bodies (--materials A[,B], or --E, --nu and --gamma or --surface-energy) and --radius",
        {"bounce contact resistance --materials water-ice --radius 1e-7",
         "bounce contact resistance --E 7e9 --nu 0.25 --density 1000 --surface-energy 0.1 --radius 1e-7 --xi-crit 8e-10 "
         "--json"}}},
      {"atlas build",
       {"--materials, the model, --radius MIN:MAX:N, --velocity MIN:MAX:N and -o FILE",
        {"bounce atlas build --model viscoelastic --A 1e-6 --materials ice-bshp96 --radius 1e-3:1e-2:4 "
         "--velocity 0.1:10:5 --tol 1e-3 -o ice.h5"}}},
      {"atlas query",
       {"an atlas file (bounce atlas build), --radius and --velocity",
        {"bounce atlas build --model viscoelastic --A 1e-6 --materials ice-bshp96 --radius 1e-3:1e-2:4 "
         "--velocity 0.1:10:5 --tol 1e-3 -o ice.h5 && bounce atlas query ice.h5 --radius 3e-3 --radius2 4e-3 "
         "--velocity 1 --json"}}},
      {"atlas export",
       {"an atlas file (bounce atlas build) and --csv",
        {"bounce atlas build --model viscoelastic --A 1e-6 --materials ice-bshp96 --radius 1e-3:1e-2:4 "
         "--velocity 0.1:10:5 --tol 1e-3 -o ice.h5 && bounce atlas export ice.h5 --csv"}}},
      {"aggregate build",
       {"--kind bpca|bcca, --n, --radius, --material (or --density) and -o FILE.data",
        {"bounce aggregate build --kind bpca --n 1000 --radius 1e-7 --material water-ice --seed 1 -o bpca.data",
         "bounce aggregate build --kind bcca --n 1024 --radius 1e-7 --material water-ice --seed 1 -o bcca.data "
         "--json"}}},
  };
}

const Steps& steps() {
  static const Steps table = [] {
    Steps all = command_steps();
    all.merge(subcommand_steps());
    return all;
  }();
  return table;
}

}  // namespace

std::string full_name(const CLI::App& command) {
  const CLI::App* parent = command.get_parent();
  return parent != nullptr && parent->get_parent() != nullptr ? parent->get_name() + " " + command.get_name()
                                                              : command.get_name();
}

const FirstSteps* first_steps(std::string_view command) {
  const auto it = steps().find(command);
  return it == steps().end() ? nullptr : &it->second;
}

std::string ExamplesFormatter::make_usage(const CLI::App* app, std::string name) const {
  std::string out = CLI::Formatter::make_usage(app, std::move(name));
  const FirstSteps* s = app->get_parent() != nullptr ? first_steps(full_name(*app)) : nullptr;
  if (s == nullptr || s->examples.empty()) return out;
  out += "\nExamples:\n";
  for (const std::string_view e : s->examples) out += "  " + std::string(e) + "\n";
  return out;
}

}  // namespace bounce::cli

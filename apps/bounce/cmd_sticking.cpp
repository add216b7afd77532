// `bounce sticking`: the sticking velocity of an adhesive model (SPEC §7), alone or
// against the radius (K13 fig. 5, right), beside the closed forms.
#include <cmath>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "bounce/analysis/sticking.hpp"
#include "bounce/analytic/adhesive.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "cli.hpp"
#include "commands.hpp"

namespace bounce::cli {

namespace {

struct StickingCommand {
  explicit StickingCommand(CLI::App* app) : bodies(app), numbers(app), model(app, numbers) {}
  BodyOptions bodies;
  NumberOptions numbers;
  ModelOptions model;
  bool json = false;
  bool log = false;
  bool progress = false;
  std::string radii;
};

// The closed forms beside a sticking velocity.
nlohmann::json closed_forms_json(const Pair& pair, const models::ModelSpec& spec) {
  const double gamma = pair.require_surface_energy("model " + spec.name);
  const double r = pair.effective_radius(), e = pair.effective_modulus(), m = pair.effective_mass();
  nlohmann::json j;
  j["sticking_velocity_jkr"] = analytic::sticking_velocity_jkr(m, r, e, gamma);
  j["sticking_velocity_k13_25"] = analytic::sticking_velocity_k13(m, r, e, gamma);
  if (spec.name == "adhesive-viscoelastic") {
    const double w0 = analytic::tensile_work(r, e, gamma);
    j["sticking_velocity_bp04_8_100"] = sticking_velocity_bp04(pair, spec);
    j["sticking_velocity_bp04_8_101"] = analytic::sticking_velocity_bp04_leading(
        w0, m, models::dissipative_constant(spec, pair), models::hertz_geometry(spec, pair).force_constant);
    j["tensile_work_bp04_8_95"] = w0;
  }
  j["effective_radius"] = r;
  return j;
}

nlohmann::json sticking_json(const Pair& pair, const models::ModelSpec& spec, const CollideOptions& options,
                             double tolerance) {
  const StickingVelocity s = sticking_velocity(pair, spec, options, tolerance);
  nlohmann::json j = closed_forms_json(pair, spec);
  j["sticking_velocity"] = s.velocity;
  j["bracket"] = {s.lower, s.upper};
  j["collisions"] = s.collisions;
  j["relative_tolerance"] = tolerance;
  return j;
}

int run_sticking(const StickingCommand& c) {
  const models::ModelSpec spec = c.model.spec();
  const CollideOptions options = c.model.collide_options();
  const double tolerance = c.numbers.get("--relative-tolerance").value_or(1e-6);
  require_open_interval("relative_tolerance", tolerance, 1e-12, 0.1, "relative tolerance");
  if (c.radii.empty()) {
    const nlohmann::json j = sticking_json(c.bodies.pair(), spec, options, tolerance);
    if (c.json) {
      print_json(j);
    } else {
      std::cout << fmt::format("sticking velocity {:.8g} m/s (model {}, bracket [{:.8g}, {:.8g}], {} collisions)\n",
                               j["sticking_velocity"].get<double>(), spec.name, j["bracket"][0].get<double>(),
                               j["bracket"][1].get<double>(), j["collisions"].get<int>());
      std::cout << fmt::format("elastic JKR (exact)  {:.8g} m/s\nK13 (25)             {:.8g} m/s\n",
                               j["sticking_velocity_jkr"].get<double>(), j["sticking_velocity_k13_25"].get<double>());
      if (j.contains("sticking_velocity_bp04_8_100")) {
        std::cout << fmt::format("BP04 (8.100)         {:.8g} m/s\nBP04 (8.101)         {:.8g} m/s\n",
                                 j["sticking_velocity_bp04_8_100"].get<double>(),
                                 j["sticking_velocity_bp04_8_101"].get<double>());
      }
    }
    return 0;
  }
  const auto radii = parse_range("--radii", c.radii, c.log);
  if (radii.front() <= 0.0) throw InvalidArgument("--radii", c.radii, "radii > 0 m (LO > 0)");
  Progress progress("bounce sticking", c.progress);
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const Pair pair = c.bodies.pair(radii[i]);
    nlohmann::json j;
    try {
      j = sticking_json(pair, spec, options, tolerance);
    } catch (const NumericalError& e) {  // e.g. no threshold below the sound speed: reported, not fatal
      j = closed_forms_json(pair, spec);
      j["sticking_velocity"] = nullptr;
      j["note"] = e.what();
    }
    j["radius"] = radii[i];
    rows.push_back(j);
    progress(i + 1, radii.size());
  }
  if (c.json) {
    print_json(rows);
    return 0;
  }
  std::ostringstream text;
  // A radius without a threshold has an empty sticking_velocity and the reason in `note`.
  text << "radius,effective_radius,sticking_velocity,sticking_velocity_jkr,sticking_velocity_k13_25,note\n";
  for (const auto& j : rows) {
    const bool found = !j["sticking_velocity"].is_null();
    text << csv_row({j["radius"].get<double>(), j["effective_radius"].get<double>()}) << ','
         << (found ? csv_row({j["sticking_velocity"].get<double>()}) : std::string()) << ','
         << csv_row({j["sticking_velocity_jkr"].get<double>(), j["sticking_velocity_k13_25"].get<double>()}) << ','
         << (found ? std::string() : '"' + j["note"].get<std::string>() + '"') << '\n';
  }
  std::cout << text.str();
  return 0;
}

}  // namespace

Command add_sticking_command(CLI::App& root) {
  auto* app = root.add_subcommand("sticking", "The sticking velocity of an adhesive model (and its closed forms)");
  auto c = std::make_shared<StickingCommand>(app);
  app->add_flag("--json", c->json, "print JSON");
  app->add_option("--radii", c->radii, "radii LO:HI:N of body 1 [m]: CSV of the sticking velocity (K13 fig. 5)");
  app->add_flag("--log", c->log, "geometric spacing of the radii");
  app->add_flag("--progress", c->progress, "report progress on stderr (automatic on a terminal)");
  c->numbers.add("--relative-tolerance", "relative width of the final bracket (default 1e-6)");
  return {app, [c]() { return run_sticking(*c); }};
}

}  // namespace bounce::cli

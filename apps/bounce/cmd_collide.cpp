// `bounce collide` (one collision) and `bounce curve` (a COR curve), SPEC §7.
#include <cmath>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "cli.hpp"
#include "commands.hpp"

namespace bounce::cli {

namespace {

struct CollideCommand {
  explicit CollideCommand(CLI::App* app) : bodies(app), numbers(app), model(app, numbers) {}
  BodyOptions bodies;
  NumberOptions numbers;
  ModelOptions model;
  bool json = false;
  bool trajectory = false;
  bool csv = false;
  bool log = false;
  bool progress = false;
  std::string velocities;
};

// kappa, g* and the Hertz scales for the Hertz-type models.
void add_scales(nlohmann::json& out, const Pair& pair, const models::ModelSpec& spec, double velocity) {
  if (spec.name == "power-law") return;
  const ViscoelasticScales s = viscoelastic_scales(pair, spec, velocity);
  out["dissipative_constant"] = s.dissipative_constant;
  out["force_constant"] = s.force_constant;
  out["kappa"] = s.kappa;
  if (std::isfinite(s.characteristic_velocity)) out["characteristic_velocity"] = s.characteristic_velocity;
  out["reference_overlap"] = s.reference_overlap;
  out["hertz_contact_time"] = s.hertz_contact_time;
}

int run_collide(const CollideCommand& c) {
  const Pair pair = c.bodies.pair();
  const models::ModelSpec spec = c.model.spec();
  CollideOptions options = c.model.collide_options();
  options.record_trajectory = c.trajectory;
  const double velocity = require_positive(
      "velocity", c.numbers.require("--velocity", "an impact velocity > 0 m/s"), "impact velocity [m/s]");
  const auto outcome = collide(pair, spec, velocity, options);
  if (c.csv) {
    if (!c.trajectory) throw InvalidArgument("--csv", "given", "--trajectory with --csv (the trajectory as CSV)");
    std::ostringstream text;
    text << "time,overlap,rate,contact_radius,elastic_force,dissipative_force,kinetic,elastic,"
            "bulk_dissipated\n";
    for (const auto& s : outcome.trajectory) {
      text << csv_row({s.time, s.overlap, s.rate, s.contact_radius, s.elastic_force, s.dissipative_force,
                       s.kinetic, s.elastic, s.bulk_dissipated})
           << '\n';
    }
    std::cout << text.str();
    return 0;
  }
  nlohmann::json out = outcome_json(outcome, c.trajectory);
  out["model"] = spec.name;
  out["contact_end"] = std::string(dynamics::to_string(spec.end_rule));
  out["velocity"] = velocity;
  add_scales(out, pair, spec, velocity);
  out["pair"] = pair_json(pair);
  if (c.json) {
    print_json(out);
    return 0;
  }
  std::cout << fmt::format("model {} (contact end: {}, method: {}) at {:.6g} m/s\n", spec.name,
                           dynamics::to_string(spec.end_rule), outcome.method, velocity);
  if (out.contains("kappa")) {
    std::cout << fmt::format("kappa = {:.6g} (BP04 (8.70))", out["kappa"].get<double>());
    if (out.contains("characteristic_velocity")) {
      std::cout << fmt::format(", g* = {:.6g} m/s", out["characteristic_velocity"].get<double>());
    }
    std::cout << "\n";
  }
  std::cout << fmt::format("cor          e   = {:.12g}\noutcome          = {}\n", outcome.cor,
                           dynamics::to_string(outcome.outcome));
  std::cout << fmt::format("contact time t_c = {:.6g} s\nmax overlap      = {:.6g} m\n", outcome.contact_time,
                           outcome.max_overlap);
  const auto& e = outcome.energy;
  std::cout << fmt::format("energy [J]: initial {:.6g}, final {:.6g}, bulk dissipated {:.6g}, left elastic {:.6g}\n",
                           e.initial_kinetic, e.final_kinetic, e.bulk_dissipated, e.elastic_remaining);
  for (const auto& w : outcome.warnings) std::cout << "warning: " << w << "\n";
  return 0;
}

int run_curve(const CollideCommand& c) {
  const Pair pair = c.bodies.pair();
  const models::ModelSpec spec = c.model.spec();
  const CollideOptions options = c.model.collide_options();
  if (c.velocities.empty()) throw InvalidArgument("--velocities", "(not given)", "LO:HI:N impact velocities [m/s]");
  const auto velocities = parse_range("--velocities", c.velocities, c.log);
  if (velocities.front() <= 0.0) {
    throw InvalidArgument("--velocities", c.velocities, "velocities > 0 m/s (LO > 0)");
  }
  Progress progress("bounce curve", c.progress);
  const auto outcomes = collide_curve(pair, spec, velocities, options,
                                      [&](std::size_t done, std::size_t total) { progress(done, total); });
  if (c.json) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      nlohmann::json j = outcome_json(outcomes[i], false);
      j["velocity"] = velocities[i];
      out.push_back(j);
    }
    print_json(out);
    return 0;
  }
  // CSV (the default output of `curve`).
  std::ostringstream text;
  text << "velocity,cor,outcome,contact_time,max_overlap,bulk_dissipated\n";
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const auto& o = outcomes[i];
    const std::string numbers = csv_row({velocities[i], o.cor});
    text << numbers << ',' << dynamics::to_string(o.outcome) << ','
         << csv_row({o.contact_time, o.max_overlap, o.energy.bulk_dissipated}) << '\n';
  }
  std::cout << text.str();
  return 0;
}

void add_output_flags(CLI::App* app, CollideCommand& c) {
  app->add_flag("--json", c.json, "print JSON");
}

}  // namespace

Command add_collide_command(CLI::App& root) {
  auto* app = root.add_subcommand("collide", "One head-on collision: COR, outcome, contact time, energy budget");
  auto c = std::make_shared<CollideCommand>(app);
  c->numbers.add("--velocity", "impact velocity g [m/s]");
  add_output_flags(app, *c);
  app->add_flag("--trajectory", c->trajectory, "include the trajectory (direct integration)");
  app->add_flag("--csv", c->csv, "with --trajectory: print the trajectory as CSV");
  return {app, [c]() { return run_collide(*c); }};
}

Command add_curve_command(CLI::App& root) {
  auto* app = root.add_subcommand("curve", "COR against impact velocity (CSV by default)");
  auto c = std::make_shared<CollideCommand>(app);
  app->add_option("--velocities", c->velocities, "impact velocities LO:HI:N [m/s]");
  app->add_flag("--log", c->log, "geometric spacing of the velocities");
  app->add_flag("--csv", c->csv, "print CSV (the default)");
  add_output_flags(app, *c);
  app->add_flag("--progress", c->progress, "report progress on stderr (automatic on a terminal)");
  return {app, [c]() { return run_curve(*c); }};
}

}  // namespace bounce::cli

// `bounce collide` (one collision) and `bounce curve` (a COR curve), SPEC §7.
#include <cmath>
#include <optional>
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
  bool closed_forms = false;
  std::string velocities;
  std::string radii;
};

// kappa, g* and the Hertz scales for the Hertz-type models.
void add_scales(nlohmann::json& out, const Pair& pair, const models::ModelSpec& spec, double velocity) {
  if (spec.name == "power-law" || models::model_info(spec.name).dynamic_contact) return;
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
  if (auto follow = c.numbers.get("--follow")) {
    options.follow_time = require_positive("follow", *follow, "a time > 0 s to follow a sticking collision");
  }
  const double velocity = require_positive(
      "velocity", c.numbers.require("--velocity", "an impact velocity > 0 m/s"), "impact velocity [m/s]");
  const auto outcome = collide(pair, spec, velocity, options);
  if (c.csv) {
    if (!c.trajectory) throw InvalidArgument("--csv", "given", "--trajectory with --csv (the trajectory as CSV)");
    std::ostringstream text;
    text << "time,overlap,rate,contact_radius,elastic_force,dissipative_force,beta,kinetic,elastic,surface,"
            "bulk_dissipated,crack_dissipated\n";
    for (const auto& s : outcome.trajectory) {
      text << csv_row({s.time, s.overlap, s.rate, s.contact_radius, s.elastic_force, s.dissipative_force,
                       s.effective_surface_energy_ratio, s.kinetic, s.elastic, s.surface, s.bulk_dissipated,
                       s.crack_dissipated})
           << '\n';
    }
    std::cout << text.str();
    return 0;
  }
  nlohmann::json out = outcome_json(outcome, c.trajectory);
  out["model"] = spec.name;
  out["contact_end"] = std::string(models::to_string(spec.end_rule));
  out["velocity"] = velocity;
  add_scales(out, pair, spec, velocity);
  if (models::model_info(spec.name).adhesive || spec.yield_strength) {
    out["closed_forms"] = adhesive_closed_forms(pair, spec, velocity);
  }
  std::optional<MergedBody> merged;
  if (outcome.outcome == dynamics::Outcome::stick) {
    merged = merged_body(pair, velocity);
    out["merged"] = {{"mass", std::isfinite(merged->mass) ? nlohmann::json(merged->mass) : nlohmann::json("wall")},
                     {"velocity", merged->velocity},
                     {"frame", "body 2 at rest before the impact"}};
  }
  out["pair"] = pair_json(pair);
  if (c.json) {
    print_json(out);
    return 0;
  }
  std::cout << fmt::format("model {} (contact end: {}, method: {}) at {:.6g} m/s\n", spec.name,
                           models::to_string(spec.end_rule), outcome.method, velocity);
  if (out.contains("kappa")) {
    std::cout << fmt::format("kappa = {:.6g} (BP04 (8.70))", out["kappa"].get<double>());
    if (out.contains("characteristic_velocity")) {
      std::cout << fmt::format(", g* = {:.6g} m/s", out["characteristic_velocity"].get<double>());
    }
    std::cout << "\n";
  }
  std::cout << fmt::format("cor          e   = {:.12g}\noutcome          = {}\n", outcome.cor,
                           dynamics::to_string(outcome.outcome));
  if (outcome.tangential) {
    const auto& t = *outcome.tangential;
    std::cout << fmt::format(
        "tangential   e^T = {:.12g} ({} asperity breaks resolved, {:.3g} s averaged; energy [J]: initial {:.6g}, "
        "final {:.6g}, asperities {:.6g}, left {:.6g}, from the stiffness change {:.6g})\n",
        t.cor, t.breaks, t.averaged_time, t.initial_kinetic, t.final_kinetic, t.asperity_dissipated, t.stored_at_end,
        t.stiffness_work);
  }
  std::cout << fmt::format("contact time t_c = {:.6g} s{}\nmax overlap      = {:.6g} m\n", outcome.contact_time,
                           outcome.outcome == dynamics::Outcome::stick ? " (when sticking became certain)" : "",
                           outcome.max_overlap);
  if (merged && std::isfinite(merged->mass)) {
    std::cout << fmt::format("merged           = {:.6g} kg at {:.6g} m/s (frame of body 2 before the impact)\n",
                             merged->mass, merged->velocity);
  } else if (merged) {
    std::cout << "merged           = the grain stays on the wall\n";
  }
  const auto& e = outcome.energy;
  std::cout << fmt::format(
      "energy [J]: initial {:.6g}, final {:.6g}, bulk dissipated {:.6g}, crack dissipated {:.6g}, plastic {:.6g}, "
      "left elastic {:.6g}, left surface {:.6g}\n",
      e.initial_kinetic, e.final_kinetic, e.bulk_dissipated, e.crack_dissipated, e.plastic_dissipated,
      e.elastic_remaining, e.surface_remaining);
  if (out.contains("closed_forms")) {
    for (const auto& [key, value] : out["closed_forms"].items()) {
      std::cout << fmt::format("  {:<28} {:.6g}\n", key, value.get<double>());
    }
  }
  for (const auto& n : outcome.notes) std::cout << "note: " << n << "\n";
  for (const auto& w : outcome.warnings) std::cout << "warning: " << w << "\n";
  return 0;
}

// One CSV row of a curve: the sweep value(s), then the outcome.
std::string curve_row(const std::vector<double>& sweep, const dynamics::CollisionOutcome& o,
                      const std::optional<nlohmann::json>& closed) {
  std::string row = csv_row(sweep) + ',' + csv_row({o.cor}) + ',' + std::string(dynamics::to_string(o.outcome)) + ',' +
                    csv_row({o.contact_time, o.max_overlap, o.energy.bulk_dissipated, o.energy.crack_dissipated});
  if (closed) {
    row += ',' + csv_row({(*closed)["e_jkr"].get<double>(), closed->value("e_d", 1.0), closed->value("e_i", 0.0)});
  }
  return row;
}

int run_curve(const CollideCommand& c) {
  const models::ModelSpec spec = c.model.spec();
  const CollideOptions options = c.model.collide_options();
  const bool by_radius = !c.radii.empty();
  if (by_radius == !c.velocities.empty()) {
    throw InvalidArgument("--velocities", c.velocities.empty() ? "(not given)" : c.velocities,
                          "either --velocities LO:HI:N, or --radii LO:HI:N with --velocity V");
  }
  if (c.closed_forms && !models::model_info(spec.name).adhesive) {
    throw InvalidArgument("--closed-forms", "given", "an adhesive model (the columns are K13 (24), (26), (27))");
  }
  std::vector<double> sweep;
  double fixed_velocity = 0.0;
  if (by_radius) {
    sweep = parse_range("--radii", c.radii, c.log);
    if (sweep.front() <= 0.0) throw InvalidArgument("--radii", c.radii, "radii > 0 m (LO > 0)");
    fixed_velocity = require_positive("velocity", c.numbers.require("--velocity", "an impact velocity > 0 m/s with --radii"),
                                      "impact velocity [m/s]");
  } else {
    sweep = parse_range("--velocities", c.velocities, c.log);
    if (sweep.front() <= 0.0) throw InvalidArgument("--velocities", c.velocities, "velocities > 0 m/s (LO > 0)");
  }
  Progress progress("bounce curve", c.progress);
  std::vector<dynamics::CollisionOutcome> outcomes;
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < sweep.size(); ++i) {
    pairs.push_back(by_radius ? c.bodies.pair(sweep[i]) : c.bodies.pair());
    outcomes.push_back(collide(pairs.back(), spec, by_radius ? fixed_velocity : sweep[i], options));
    progress(i + 1, sweep.size());
  }
  // Refine every stick/bounce change between neighbouring velocities (relative 1e-6).
  nlohmann::json boundaries = nlohmann::json::array();
  if (!by_radius) {
    for (std::size_t i = 0; i + 1 < sweep.size(); ++i) {
      if (outcomes[i].outcome == outcomes[i + 1].outcome) continue;
      double lo = sweep[i], hi = sweep[i + 1];
      const auto low_outcome = outcomes[i].outcome;
      while (hi - lo > 1e-6 * hi) {
        const double mid = std::sqrt(lo * hi);
        (collide(pairs.front(), spec, mid, options).outcome == low_outcome ? lo : hi) = mid;
      }
      boundaries.push_back({{"velocity", std::sqrt(lo * hi)},
                            {"below", std::string(dynamics::to_string(low_outcome))},
                            {"above", std::string(dynamics::to_string(outcomes[i + 1].outcome))}});
    }
  }
  auto closed = [&](std::size_t i) -> std::optional<nlohmann::json> {
    if (!c.closed_forms) return std::nullopt;
    return adhesive_closed_forms(pairs[i], spec, by_radius ? fixed_velocity : sweep[i]);
  };
  if (c.json) {
    nlohmann::json points = nlohmann::json::array();
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      nlohmann::json j = outcome_json(outcomes[i], false);
      if (by_radius) {
        j["radius"] = sweep[i];
        j["effective_radius"] = pairs[i].effective_radius();
        j["velocity"] = fixed_velocity;
      } else {
        j["velocity"] = sweep[i];
      }
      if (auto cf = closed(i)) j["closed_forms"] = *cf;
      points.push_back(j);
    }
    print_json({{"points", points}, {"boundaries", boundaries}});
    return 0;
  }
  std::ostringstream text;
  text << (by_radius ? "radius,effective_radius," : "velocity,")
       << "cor,outcome,contact_time,max_overlap,bulk_dissipated,crack_dissipated"
       << (c.closed_forms ? ",e_jkr,e_d,e_i" : "") << '\n';
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const std::vector<double> key = by_radius ? std::vector<double>{sweep[i], pairs[i].effective_radius()}
                                              : std::vector<double>{sweep[i]};
    text << curve_row(key, outcomes[i], closed(i)) << '\n';
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
  c->numbers.add("--follow", "krijt / jkr-viscoelastic: keep integrating a sticking collision until this time [s]");
  add_output_flags(app, *c);
  app->add_flag("--trajectory", c->trajectory, "include the trajectory (direct integration)");
  app->add_flag("--csv", c->csv, "with --trajectory: print the trajectory as CSV");
  return {app, [c]() { return run_collide(*c); }};
}

Command add_curve_command(CLI::App& root) {
  auto* app = root.add_subcommand("curve", "COR against impact velocity (CSV by default)");
  auto c = std::make_shared<CollideCommand>(app);
  app->add_option("--velocities", c->velocities, "impact velocities LO:HI:N [m/s]");
  app->add_option("--radii", c->radii, "radii LO:HI:N of body 1 [m] at a fixed --velocity (K13 fig. 5)");
  c->numbers.add("--velocity", "the impact velocity of a --radii sweep [m/s]");
  app->add_flag("--log", c->log, "geometric spacing of the sweep");
  app->add_flag("--closed-forms", c->closed_forms, "add K13's e_JKR (24), e_D (26), e_I (27) columns (adhesive models)");
  app->add_flag("--csv", c->csv, "print CSV (the default)");
  add_output_flags(app, *c);
  app->add_flag("--progress", c->progress, "report progress on stderr (automatic on a terminal)");
  return {app, [c]() { return run_curve(*c); }};
}

}  // namespace bounce::cli

// `bounce rules`: post-collision velocities and spins (BSHP96 (42)-(43) with the impulse
// of analysis/rules.hpp), JSON in, JSON out.
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include <fmt/format.h>

#include "bounce/analysis/rules.hpp"
#include "bounce/core/error.hpp"
#include "cli.hpp"
#include "commands.hpp"

namespace bounce::cli {

namespace {

struct RulesCommand {
  explicit RulesCommand(CLI::App* app) : bodies(app), numbers(app), model(app, numbers) {}
  BodyOptions bodies;
  NumberOptions numbers;
  ModelOptions model;
  std::string input = "-";
};

Vector3 vector_field(const nlohmann::json& j, const std::string& where, const char* key, bool required) {
  if (!j.contains(key)) {
    if (required) throw InvalidArgument(where + "." + key, "(not given)", "a vector [x, y, z]");
    return {0.0, 0.0, 0.0};
  }
  const auto& v = j.at(key);
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number()) {
    throw InvalidArgument(where + "." + key, v.dump(), "a vector of three numbers [x, y, z]");
  }
  return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

GrainMotion grain(const nlohmann::json& j, const std::string& key) {
  if (!j.contains(key) || !j.at(key).is_object()) {
    throw InvalidArgument(key, "(not given)", R"({"velocity": [...], "angular_velocity": [...]})");
  }
  return {vector_field(j.at(key), key, "velocity", true), vector_field(j.at(key), key, "angular_velocity", false)};
}

// Without negative zeros (cosmetic: -0.0 prints as -0.0).
Vector3 clean(Vector3 v) {
  for (double& c : v) c += 0.0;
  return v;
}

nlohmann::json motion_json(const GrainMotion& g) {
  return {{"velocity", clean(g.velocity)}, {"angular_velocity", clean(g.angular_velocity)}};
}

nlohmann::json one(const nlohmann::json& in, const Pair& pair, const models::ModelSpec& spec,
                   const CollideOptions& options) {
  if (!in.is_object()) throw InvalidArgument("input", in.dump(), "a JSON object per encounter");
  const Vector3 n = vector_field(in, "input", "normal", true);
  const GrainMotion g1 = grain(in, "grain1"), g2 = grain(in, "grain2");
  CollisionRuleResult r;
  if (in.contains("cor")) {  // given coefficients
    if (!in.at("cor").is_number()) throw InvalidArgument("cor", in.at("cor").dump(), "a number 0 <= eps^N <= 1");
    const double et = in.value("cor_tangential", 1.0);
    r = apply_restitution(pair, n, g1, g2, in.at("cor").get<double>(), et);
  } else {
    r = collide_grains(pair, spec, n, g1, g2, options);
  }
  const double m = pair.effective_mass(), kappa = pair.tangential_mass_factor();
  const double gn = r.before.normal_speed, gt = r.before.tangential_speed;
  nlohmann::json out;
  out["grain1"] = motion_json(r.grain1);
  out["grain2"] = motion_json(r.grain2);
  out["cor"] = r.cor;
  out["cor_tangential"] = r.cor_tangential;
  out["normal_velocity"] = clean(r.before.normal);
  out["tangential_velocity"] = clean(r.before.tangential);
  out["energy_change"] = r.energy_change;
  // BSHP96 (11), for comparison.
  out["energy_change_bshp96_11"] = 0.5 * m * gn * gn * (r.cor * r.cor - 1.0) +
                                   0.5 * m * kappa * gt * gt * (r.cor_tangential * r.cor_tangential - 1.0);
  return out;
}

int run_rules(const RulesCommand& c) {
  std::string text;
  if (c.input == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
  } else {
    std::ifstream file(c.input);
    if (!file) throw InvalidArgument("--input", c.input, "a readable JSON file (or - for standard input)");
    text.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  }
  nlohmann::json in;
  try {
    in = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InvalidArgument("--input", c.input == "-" ? "(standard input)" : c.input,
                          fmt::format("JSON ({})", e.what()));
  }
  const Pair pair = c.bodies.pair();
  const models::ModelSpec spec = c.model.spec();
  const CollideOptions options = c.model.collide_options();
  if (in.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& item : in) out.push_back(one(item, pair, spec, options));
    print_json(out);
  } else {
    print_json(one(in, pair, spec, options));
  }
  return 0;
}

}  // namespace

Command add_rules_command(CLI::App& root) {
  auto* app = root.add_subcommand(
      "rules",
      "Post-collision velocities and spins (BSHP96 (42)-(43)): JSON in, JSON out. An encounter is "
      R"({"normal": [n], "grain1": {"velocity": [v], "angular_velocity": [w]}, "grain2": {...}})"
      " with n from grain 2 to grain 1, optionally \"cor\" and \"cor_tangential\" (else the model's); "
      "an array of them gives an array");
  auto c = std::make_shared<RulesCommand>(app);
  app->add_option("--input", c->input, "JSON file (default -: standard input)");
  return {app, [c]() { return run_rules(*c); }};
}

}  // namespace bounce::cli

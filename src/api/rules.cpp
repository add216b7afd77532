// The front door's `rules`: post-collision velocities and spins of JSON encounters (BSHP96
// (42)-(43) with the impulse of analysis/rules.hpp).
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "binding.hpp"
#include "bounce/analysis/rules.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/pair_parameters.hpp"

namespace bounce::api {

namespace {

using analysis::GrainMotion;
using analysis::Vector3;

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
std::vector<double> clean(Vector3 v) {
  for (double& c : v) c += 0.0;
  return {v.begin(), v.end()};
}

Record motion_record(const GrainMotion& g) {
  return Record().set("velocity", clean(g.velocity)).set("angular_velocity", clean(g.angular_velocity));
}

// The pair, and the model once an encounter needs it (one without given coefficients).
struct Encounters {
  detail::Bound bound;
  Pair pair;
  std::optional<Case> with_model;
  const Case& model_case() {
    if (!with_model) with_model = detail::make_case(bound);
    return *with_model;
  }
};

Record one(const nlohmann::json& in, Encounters& c) {
  if (!in.is_object()) throw InvalidArgument("encounter", in.dump(), "a JSON object per encounter");
  const Vector3 n = vector_field(in, "encounter", "normal", true);
  const GrainMotion g1 = grain(in, "grain1"), g2 = grain(in, "grain2");
  analysis::CollisionRuleResult r;
  const bool given_n = in.contains("cor"), given_t = in.contains("cor_tangential");
  if (given_n && !in.at("cor").is_number()) throw InvalidArgument("cor", in.at("cor").dump(), "a number 0 <= eps^N <= 1");
  if (given_t && (!in.at("cor_tangential").is_number() || std::abs(in.at("cor_tangential").get<double>()) > 1.0)) {
    // A given eps^T beyond 1 in size would create energy (BSHP96 (11)).
    throw InvalidArgument("cor_tangential", in.at("cor_tangential").dump(), "a number -1 <= eps^T <= 1 (BSHP96 (2))");
  }
  std::vector<std::string> warnings;
  if (given_n && given_t) {
    r = analysis::apply_restitution(c.pair, n, g1, g2, in.at("cor").get<double>(), in.at("cor_tangential").get<double>());
  } else {
    // What is not given comes from the model (eps^T = 1 with a given eps^N: no tangential loss).
    const Case& m = c.model_case();
    const bool need_model = !given_n || given_t;
    r = need_model ? analysis::collide_grains(m.pair, m.model, n, g1, g2, m.options) : analysis::CollisionRuleResult{};
    const double en = given_n ? in.at("cor").get<double>() : r.cor;
    const double et = given_t ? in.at("cor_tangential").get<double>() : given_n ? 1.0 : r.cor_tangential;
    if (std::abs(et) > 1.0) {
      warnings.push_back(fmt::format("the model gives |eps^T| = {:.6g} > 1: the published asperity law returns more "
                                     "tangential energy than it got (docs/tangential.md)", std::abs(et)));
    }
    r = analysis::apply_restitution(c.pair, n, g1, g2, en, et);
  }
  const double m = c.pair.effective_mass(), kappa = c.pair.tangential_mass_factor();
  const double gn = r.before.normal_speed, gt = r.before.tangential_speed;
  Record out;
  out.set("grain1", motion_record(r.grain1));
  out.set("grain2", motion_record(r.grain2));
  out.set("cor", r.cor);
  out.set("cor_tangential", r.cor_tangential);
  out.set("normal_velocity", clean(r.before.normal));
  out.set("tangential_velocity", clean(r.before.tangential));
  out.set("energy_change", r.energy_change);
  out.set("warnings", warnings);
  // BSHP96 (11), for comparison.
  out.set("energy_change_bshp96_11", 0.5 * m * gn * gn * (r.cor * r.cor - 1.0) +
                                         0.5 * m * kappa * gt * gt * (r.cor_tangential * r.cor_tangential - 1.0));
  return out;
}

}  // namespace

Value rules(const Inputs& inputs, std::string_view encounters) {
  nlohmann::json in;
  try {
    in = nlohmann::json::parse(encounters);
  } catch (const nlohmann::json::exception& e) {  // parse errors, and numbers beyond double (1e400)
    throw InvalidArgument("encounters", "(not JSON)", fmt::format("JSON (this is {})", json_error_words(e.id, e.what())));
  }
  detail::Bound bound = detail::bind_inputs(command("rules"), inputs);
  Pair pair = bounce::make_pair(bound.pair);
  Encounters c{std::move(bound), std::move(pair), std::nullopt};
  if (!in.is_array()) return one(in, c);
  Value::List out;
  for (const auto& item : in) out.push_back(one(item, c));
  return out;
}

}  // namespace bounce::api

// No normal COR that collide or curve prints is outside [0, 1] (issue 40, A1): neither the
// computed `cor` nor a closed form (K13 (24), (26), (27), (29), BP04 (8.98)) beside it, which
// is null where it leaves its validity. Randomized with a fixed seed over the built-in
// materials, radii, models, viscous times and speeds as users type them (far outside the
// models' validity too), through the front door the CLI and Python call. The tangential
// eps^T keeps its own range (docs/tangential.md) and is not drawn here.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "bounce/api/front_door.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/materials_table.hpp"

using namespace bounce;

namespace {

// Every COR of a collision's Record (a collide result or a curve point) is in [0, 1], and a
// null closed form comes with a warning; returns how many CORs it checked.
int check_cors(const Record& r, const std::string& what) {
  int checked = 1;
  const double cor = r.at("cor").number();
  EXPECT_TRUE(cor >= 0.0 && cor <= 1.0) << what << ": cor = " << cor;
  if (!r.contains("closed_forms")) return checked;
  const Record& closed = r.at("closed_forms").record();
  bool any_null = false;
  for (const auto& [key, value] : closed.fields()) {
    if (key.rfind("e_", 0) != 0) continue;
    ++checked;
    any_null = any_null || value.is_null();
    if (!value.is_null()) {
      EXPECT_TRUE(value.number() >= 0.0 && value.number() <= 1.0) << what << ": " << key << " = " << value.number();
    }
  }
  EXPECT_EQ(any_null, closed.contains("warnings")) << what;
  return checked;
}

}  // namespace

// The issue's two calls, as the CLI makes them: e_d and e_i were -1.71 and 1.39, and -7.1e3 to
// -1.4e5 and 7.1e3 to 1.4e5 along the curve.
TEST(CorRange, IssueCallsPrintNullClosedForms) {
  const Record one = api::collide({{"material", "water-ice"}, {"radius", "5e-8"}, {"model", "krijt"},
                                   {"tvis", "1e-11"}, {"velocity", "10"}});
  const Record& closed = one.at("closed_forms").record();
  EXPECT_TRUE(closed.at("e_d").is_null());
  EXPECT_TRUE(closed.at("e_i").is_null());
  EXPECT_NE(closed.at("warnings").list().front().text().find("5.57 A/t_H <= 1"), std::string::npos);
  check_cors(one, "collide");
  const Record curve = api::curve({{"material", "quartz"}, {"radius", "1e-8"}, {"model", "krijt"}, {"tvis", "1e-8"},
                                   {"velocities", "0.001:2900:5"}, {"log", true}, {"closed_forms", true}});
  for (const Value& point : curve.at("points").list()) {
    EXPECT_TRUE(point.record().at("closed_forms").record().at("e_d").is_null());
    check_cors(point.record(), "curve");
  }
}

TEST(CorRange, RandomCollisionsAndCurvesPrintNoCorOutsideTheUnitInterval) {
  std::mt19937_64 rng(20261206);  // fixed: the same cases every run
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto decade = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * u(rng)); };
  const auto pick = [&](const std::vector<std::string>& from) {
    return from[std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(rng)];
  };
  const std::vector<std::string> materials = MaterialTable::builtin().names();
  const std::vector<std::string> models = {"hertz", "viscoelastic", "viscoelastic-shifted", "adhesive-viscoelastic",
                                           "jkr-viscoelastic", "krijt", "maugis-viscoelastic"};
  int printed = 0, cors = 0;
  for (int k = 0; k < 60; ++k) {
    api::Inputs in{{"material", pick(materials)},
                   {"radius", fmt::format("{:.3g}", decade(-8, -2))},
                   {"model", pick(models)}};
    // T_vis from 1e-14 s to 1e-7 s: K13's ice value 1e-11 s, and the issue's 1e-8 s for 10 nm quartz.
    if (std::get<std::string>(in.at("model")) != "hertz") in["tvis"] = fmt::format("{:.3g}", decade(-14, -7));
    const double v = decade(-3, 2.5);
    const std::string what = fmt::format("case {} v = {:.3g}:{}", k, v, [&] {
      std::string s;
      for (const auto& [name, value] : in) s += " --" + name + " " + std::get<std::string>(value);
      return s;
    }());
    try {
      api::Inputs one = in;
      one["velocity"] = fmt::format("{:.3g}", v);
      cors += check_cors(api::collide(one), what);
      api::Inputs sweep = in;
      sweep["velocities"] = fmt::format("{:.3g}:{:.3g}:3", v / 30.0, v);
      sweep["log"] = true;
      const std::string& model = std::get<std::string>(in.at("model"));
      sweep["closed_forms"] = model != "hertz" && model != "viscoelastic" && model != "viscoelastic-shifted";
      api::curve(sweep, [&](const Record& point) { cors += check_cors(point, what); }, {}, false);
      ++printed;
    } catch (const Error&) {  // refused (exit 2) or not computable (exit 3): nothing is printed
    }
  }
  // Most cases print (a draw that refuses everything would prove nothing).
  EXPECT_GE(printed, 30);
  EXPECT_GE(cors, 200);
}

// An overdamped contact creeps apart with a rebound speed near 0 that the event location placed a
// hair below it: main printed cor = -7.96e-15 (viscoelastic integrated at A = 1e3 t_H) and
// -8.6e-13 (a linear power law at kappa = 90). Within the tolerance that is 0.
TEST(CorRange, OverdampedIntegrationsPrintNoNegativeCor) {
  const Record viscous = api::collide({{"material", "water-ice"}, {"radius", "1e-6"}, {"model", "viscoelastic"},
                                       {"method", "integrate"}, {"A", "1e-5"}, {"velocity", "1"}});
  check_cors(viscous, "viscoelastic A = 1e-5 s");
  const Record linear = api::collide({{"material", "water-ice"}, {"radius", "1e-6"}, {"model", "power-law"},
                                      {"power_d1", "1e10"}, {"power_d2", "9e6"}, {"power_alpha", "1"},
                                      {"power_gamma", "0"}, {"power_beta", "1"}, {"velocity", "1"}});
  check_cors(linear, "power law kappa = 90");
}

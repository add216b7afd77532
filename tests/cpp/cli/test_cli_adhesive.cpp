// CLI contract for the adhesive models: collide, curve, sticking (docs/cli.md) and bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"

using bounce::testing::count_lines;
using bounce::testing::expect_rejected;
using bounce::testing::run_cli;

namespace {
std::vector<std::string> k13(std::string command, std::vector<std::string> more) {
  std::vector<std::string> args = {command, "--material", "water-ice", "--radius", "2.035e-6", "--model", "krijt",
                                   "--tvis", "1e-11"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}
// The same for a sweep over radii, which sets body 1's radius itself.
std::vector<std::string> k13_radii(std::string command, std::vector<std::string> more) {
  std::vector<std::string> args = k13(std::move(command), std::move(more));
  args.erase(args.begin() + 3, args.begin() + 5);  // --radius 2.035e-6
  return args;
}
}  // namespace

TEST(CliAdhesive, CollideJson) {
  const auto r = run_cli(k13("collide", {"--velocity", "8", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "bounce");
  EXPECT_GT(j["energy"]["crack_dissipated"].get<double>(), 0.0);
  EXPECT_GT(j["energy"]["bulk_dissipated"].get<double>(), 0.0);
  EXPECT_NEAR(j["closed_forms"]["sticking_velocity_k13_25"].get<double>(),
              j["closed_forms"]["sticking_velocity_jkr"].get<double>(), 1e-3);  // 14.18 vs 14.1844
  EXPECT_FALSE(j["warnings"].empty());  // K13 (A.2), (A.4) do not hold at T_vis = 1e-11 s
  EXPECT_FALSE(j.contains("merged"));
  const auto stick = run_cli(k13("collide", {"--velocity", "1", "--json"}));
  const auto s = nlohmann::json::parse(stick.out);
  EXPECT_EQ(s["outcome"], "stick");
  EXPECT_EQ(s["cor"], 0.0);
  // Sticking grains merge: twice the mass; momentum m g = 2 m u, so u = g / 2.
  const double m = s["pair"]["effective_mass"].get<double>() * 2.0;  // one sphere (m_eff = m / 2)
  EXPECT_NEAR(s["merged"]["mass"].get<double>(), 2.0 * m, 1e-12 * m);
  EXPECT_NEAR(s["merged"]["velocity"].get<double>(), 0.5, 1e-15);
  // On a wall the grain stays.
  const auto wall = run_cli(k13("collide", {"--velocity", "0.5", "--wall", "--json"}));
  ASSERT_EQ(wall.exit_code, 0) << wall.err;
  EXPECT_EQ(nlohmann::json::parse(wall.out)["merged"]["mass"], "wall");
  EXPECT_EQ(nlohmann::json::parse(wall.out)["merged"]["velocity"], 0.0);
  // Both stiff engines, same answer (their tolerance-limited errors are ~1e-9).
  const auto cvode = run_cli(k13("collide", {"--velocity", "8", "--json", "--stiff-engine", "cvode"}));
  ASSERT_EQ(cvode.exit_code, 0) << cvode.err;
  EXPECT_NEAR(nlohmann::json::parse(cvode.out)["cor"].get<double>(), j["cor"].get<double>(), 1e-7);
}

TEST(CliAdhesive, TrajectoryAndFollow) {
  const auto r = run_cli(k13("collide", {"--velocity", "1", "--trajectory", "--csv", "--follow", "5e-8"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("beta"), std::string::npos);
  EXPECT_GT(count_lines(r.out), 500);
}

TEST(CliAdhesive, Sticking) {
  const auto r = run_cli(k13("sticking", {"--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double v_s = j["sticking_velocity"].get<double>();
  EXPECT_GT(v_s, j["sticking_velocity_jkr"].get<double>());  // viscous losses raise it (K13 §3.3)
  EXPECT_LE(j["bracket"][1].get<double>() - j["bracket"][0].get<double>(), 1e-6 * j["bracket"][1].get<double>());
  // The curve marks the boundary at the same speed (refined to 1e-6).
  const auto curve = run_cli(k13("curve", {"--velocities", "0.5:8:5", "--log", "--json"}));
  ASSERT_EQ(curve.exit_code, 0) << curve.err;
  const auto c = nlohmann::json::parse(curve.out);
  ASSERT_EQ(c["boundaries"].size(), 1u);
  EXPECT_NEAR(c["boundaries"][0]["velocity"].get<double>() / v_s, 1.0, 3e-6);
  EXPECT_EQ(c["boundaries"][0]["below"], "stick");
  const auto bp04 = run_cli({"sticking", "--material", "water-ice", "--radius", "2e-6", "--model",
                             "adhesive-viscoelastic", "--A", "1.6e-10", "--json"});
  ASSERT_EQ(bp04.exit_code, 0) << bp04.err;
  EXPECT_TRUE(nlohmann::json::parse(bp04.out).contains("sticking_velocity_bp04_8_100"));
}

TEST(CliAdhesive, Figure5Sweeps) {
  const auto curve = run_cli(k13_radii("curve", {"--radii", "1e-6:1e-4:4", "--log", "--velocity", "2", "--closed-forms"}));
  ASSERT_EQ(curve.exit_code, 0) << curve.err;
  EXPECT_EQ(curve.out.substr(0, 23), "radius,effective_radius");
  EXPECT_NE(curve.out.find("e_jkr,e_d,e_i"), std::string::npos);
  EXPECT_EQ(count_lines(curve.out), 5);
  const auto sticking = run_cli(k13_radii("sticking", {"--radii", "1e-6:1e-4:3", "--log"}));
  ASSERT_EQ(sticking.exit_code, 0) << sticking.err;
  EXPECT_EQ(count_lines(sticking.out), 4);
  expect_rejected(k13("curve", {"--radii", "1e-6:1e-4:4", "--velocity", "2"}), "--radius", "2.035e-6");
  // With slow relaxation small grains stick at every speed below the sound speed: such a
  // radius gets an empty value and the reason, the sweep goes on.
  const auto beyond = run_cli({"sticking", "--material", "water-ice", "--model", "krijt", "--tvis", "1e-10",
                               "--radii", "2e-7:2e-5:3", "--log"});
  ASSERT_EQ(beyond.exit_code, 0) << beyond.err;
  EXPECT_EQ(count_lines(beyond.out), 4);
  EXPECT_NE(beyond.out.find(",,"), std::string::npos);
  EXPECT_NE(beyond.out.find("sound speed"), std::string::npos);
}

TEST(CliAdhesive, BadInput) {
  expect_rejected(k13("collide", {"--velocity", "1", "--z0", "0"}), "--z0", "0");
  expect_rejected(k13("collide", {"--velocity", "1", "--z0", "-1e-10"}), "--z0", "-1e-10");
  expect_rejected(k13("collide", {"--velocity", "1", "--k", "0"}), "--k", "0");
  expect_rejected(k13("collide", {"--velocity", "1", "--k", "1"}), "--k", "1");
  expect_rejected({"collide", "--material", "water-ice", "--radius", "2e-6", "--model", "krijt", "--tvis", "-1e-11",
                   "--velocity", "1"},
                  "--tvis", "-1e-11");
  expect_rejected(k13("collide", {"--velocity", "1", "--gamma", "-0.1"}), "--gamma", "-0.1");
  expect_rejected(k13("collide", {"--velocity", "1", "--yield", "0"}), "--yield", "0");
  expect_rejected(k13("collide", {"--velocity", "1", "--yield", "-5e7"}), "--yield", "-5e7");
  expect_rejected({"collide", "--material", "water-ice", "--radius", "2e-6", "--model", "krijt", "--velocity", "1"},
                  "--tvis", "(not given)");
  expect_rejected({"collide", "--material", "ice-bshp96", "--radius", "2e-6", "--model", "krijt", "--tvis", "1e-11",
                   "--velocity", "1"},
                  "--gamma", "(not given)");
  expect_rejected(k13("collide", {"--velocity", "1", "--contact-end", "force"}), "--contact-end", "force");
  expect_rejected(k13("collide", {"--velocity", "1", "--method", "master"}), "--method", "master");
  expect_rejected({"sticking", "--material", "water-ice", "--radius", "2e-6", "--model", "viscoelastic", "--A", "1e-9"},
                  "--model", "viscoelastic");
  expect_rejected(k13("collide", {"--velocity", "1", "--stiff-engine", "lsoda"}), "--stiff-engine", "lsoda");
}

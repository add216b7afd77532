// CLI contract of `bounce collide`, `bounce curve` and `bounce analytic` (docs/cli.md).
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"

using bounce::testing::count_lines;
using bounce::testing::expect_rejected;
using bounce::testing::run_cli;

namespace {
std::vector<std::string> ice(std::vector<std::string> more) {
  std::vector<std::string> args = {"--material", "ice-bshp96", "--radius", "0.01", "--wall", "--A", "1e-6"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}
std::vector<std::string> command(const std::string& name, std::vector<std::string> args) {
  args.insert(args.begin(), name);
  return args;
}
}  // namespace

TEST(CliCollide, JsonContract) {
  const auto r = run_cli(command("collide", ice({"--velocity", "0.5", "--json"})));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"cor", "outcome", "contact_time", "max_overlap", "energy", "kappa", "warnings"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const char* key : {"initial_kinetic", "final_kinetic", "bulk_dissipated", "crack_dissipated"}) {
    EXPECT_TRUE(j["energy"].contains(key)) << key;
  }
  EXPECT_EQ(j["outcome"], "bounce");
  EXPECT_EQ(j["method"], "master");
  const double e = j["cor"].get<double>();
  EXPECT_GT(e, 0.9);
  EXPECT_LT(e, 1.0);
  // Energy budget closes (master: by construction; integrate: to the integration error).
  const auto& energy = j["energy"];
  EXPECT_NEAR(energy["final_kinetic"].get<double>() + energy["bulk_dissipated"].get<double>(),
              energy["initial_kinetic"].get<double>(), 1e-15);
}

TEST(CliCollide, MethodsAgreeAndTrajectory) {
  for (const char* end : {"overlap", "force"}) {
    const auto m = run_cli(command("collide", ice({"--velocity", "2", "--contact-end", end, "--json"})));
    const auto i = run_cli(command("collide", ice({"--velocity", "2", "--contact-end", end, "--method", "integrate", "--json"})));
    ASSERT_EQ(i.exit_code, 0) << i.err;
    const auto jm = nlohmann::json::parse(m.out), ji = nlohmann::json::parse(i.out);
    EXPECT_NEAR(jm["cor"].get<double>(), ji["cor"].get<double>(), 1e-9);  // master's stated + integration error
    EXPECT_NEAR(jm["contact_time"].get<double>() / ji["contact_time"].get<double>(), 1.0, 1e-9);
  }
  const auto t = run_cli(command("collide", ice({"--velocity", "2", "--trajectory", "--csv"})));
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_EQ(t.out.substr(0, t.out.find(',')), "time");
  EXPECT_GT(count_lines(t.out), 300);
}

TEST(CliCurve, CsvContract) {
  const auto r = run_cli(command("curve", ice({"--velocities", "0.01:10:7", "--log", "--csv"})));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header.substr(0, 35), "velocity,cor,outcome,contact_time,m");
  EXPECT_EQ(count_lines(r.out), 8);
  std::string first;
  std::getline(lines, first);
  EXPECT_EQ(first.substr(0, 5), "0.01,");
  double previous = 1.0;
  for (std::string row; std::getline(lines, row);) {
    const double e = std::stod(row.substr(row.find(',') + 1));
    EXPECT_LT(e, previous);  // monotone in g
    previous = e;
  }
}

TEST(CliAnalytic, ShowsAllForms) {
  const auto r = run_cli(command("analytic", ice({"--velocity", "1", "--json"})));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double exact = j["exact"]["overlap"].get<double>();
  EXPECT_GE(j["exact"]["force"].get<double>(), exact);
  // At q = 0.05 the truncated series and the Pade are within 1e-5 of the exact value.
  EXPECT_NEAR(j["series_8_89"]["bounce_overlap"].get<double>(), exact, 1e-6);
  EXPECT_NEAR(j["pade_8_92"]["bp04_printed"].get<double>(), exact, 1e-4);
  EXPECT_NEAR(j["coefficients"]["pade_bp04_printed"]["d1"].get<double>(), 2.583, 1e-12);
  const auto text = run_cli(command("analytic", ice({"--velocity", "1"})));
  EXPECT_NE(text.out.find("continued fraction BP04 (8.86)"), std::string::npos);
}

TEST(CliCollide, ValidityWarnings) {
  // 1500 m/s is not << the sound speed of ice (1961 m/s): a warning, and a result (above
  // it, the speed is refused: docs/cli.md).
  const auto r = run_cli(command("collide", ice({"--velocity", "1500", "--json"})));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["warnings"].empty());
  EXPECT_NE(j["warnings"][0].get<std::string>().find("sound speed"), std::string::npos);
  // A viscous time not << the contact time.
  const auto slow = run_cli({"collide", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-4",
                             "--velocity", "1", "--json"});
  EXPECT_NE(slow.out.find("viscous time scale"), std::string::npos);
}

TEST(CliCollide, BadInput) {
  expect_rejected(command("collide", ice({"--velocity", "0"})), "--velocity", "0");
  expect_rejected(command("collide", ice({"--velocity", "-1"})), "--velocity", "-1");
  expect_rejected(command("collide", ice({"--velocity", "nan"})), "--velocity", "nan");
  expect_rejected(command("collide", ice({})), "--velocity", "(not given)");
  expect_rejected({"collide", "--material", "ice-bshp96", "--radius", "0.01", "--A", "-1e-6", "--velocity", "1"},
                  "--A", "-1e-6");
  expect_rejected({"collide", "--material", "ice-bshp96", "--radius", "0.01", "--velocity", "1"}, "--A",
                  "(not given)");
  expect_rejected(command("collide", ice({"--velocity", "1", "--model", "rubbery"})), "--model", "rubbery");
  expect_rejected(command("collide", ice({"--velocity", "1", "--contact-end", "sometime"})), "--contact-end",
                  "sometime");
  expect_rejected(command("collide", ice({"--velocity", "1", "--method", "guess"})), "--method", "guess");
  expect_rejected(command("collide", ice({"--velocity", "1", "--model", "viscoelastic-shifted", "--method", "master"})),
                  "--method", "master");
  expect_rejected(command("curve", ice({"--velocities", "-1:1:3"})), "--velocities", "-1:1:3");
  expect_rejected(command("curve", ice({"--velocities", "1:2"})), "--velocities", "1:2");
  // One point is LO = HI (0.1:1:1 gave the single row at HI).
  expect_rejected(command("curve", ice({"--velocities", "0.1:1:1"})), "--velocities", "0.1:1:1");
  EXPECT_EQ(run_cli(command("curve", ice({"--velocities", "1:1:1"}))).exit_code, 0);
  expect_rejected({"collide", "--material", "ice-bshp96", "--material2", "steel", "--radius", "0.01", "--eta1", "1",
                   "--eta2", "2", "--velocity", "1"},
                  "--eta1", "1");
}

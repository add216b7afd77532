// The CLI contract of `bounce materials` and `bounce contact` (docs/cli.md), and the
// bad-input rule: exit code 2, one line naming the parameter, its value and the
// allowed range, nothing on stdout, no stack trace, never NaN.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"

using bounce::testing::count_lines;
using bounce::testing::expect_rejected;
using bounce::testing::run_cli;

namespace {
const std::vector<std::string> ice = {"--material", "water-ice", "--radius", "1e-6"};

std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

TEST(CliMaterials, ListsTheTable) {
  const auto r = run_cli({"materials", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.size(), 17u);
  EXPECT_EQ(j[15]["name"], "water-ice");
  EXPECT_EQ(j[15]["surface_energy"], 0.37);
  const auto text = run_cli({"materials"});
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("ag-coated-glass"), std::string::npos);
}

TEST(CliContact, JkrJsonHasTheContractFields) {
  const auto r = run_cli(with({"contact"}, with(ice, {"--law", "jkr", "--json"})));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"contact_radius", "overlap", "force", "pull_off_force",
                          "zero_load_contact_radius", "tabor_parameter", "regime_k13"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j["pull_off_force"].get<double>(), -1.5 * std::numbers::pi * 0.37 * 0.5e-6, 1e-20);
  EXPECT_NEAR(j["force"].get<double>(), 0.0, 1e-20);  // default: zero load
  EXPECT_NEAR(j["contact_radius"].get<double>(), j["zero_load_contact_radius"].get<double>(), 1e-20);
}

TEST(CliContact, AtForceAndAtOverlapAreConsistent) {
  for (const char* law : {"hertz", "jkr", "dmt", "maugis"}) {
    const auto jf_run = run_cli(with({"contact"}, with(ice, {"--law", law, "--force", "1e-6", "--json"})));
    ASSERT_EQ(jf_run.exit_code, 0) << jf_run.err;
    const auto jf = nlohmann::json::parse(jf_run.out);
    char overlap[64];
    std::snprintf(overlap, sizeof overlap, "%.17g", jf["overlap"].get<double>());
    const auto jd_run = run_cli(with({"contact"}, with(ice, {"--law", law, "--overlap", overlap, "--json"})));
    ASSERT_EQ(jd_run.exit_code, 0) << jd_run.err;
    const auto jd = nlohmann::json::parse(jd_run.out);
    // Round trip through the inverse of each law: root finders converge to ~1e-15,
    // the Maugis scan/refine to ~1e-12; 1e-9 relative is a safe common bound.
    EXPECT_NEAR(jd["force"].get<double>() / 1e-6, 1.0, 1e-9) << law;
  }
}

TEST(CliContact, CsvCurve) {
  const auto r = run_cli(with({"contact"}, with(ice, {"--law", "jkr", "--csv", "--contact-radii", "0:2e-7:21"})));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')), "contact_radius,overlap,force");
  EXPECT_EQ(count_lines(r.out), 22);
  const auto over = run_cli(with({"contact"}, with(ice, {"--law", "maugis", "--csv", "--overlaps", "-2e-9:1e-8:5"})));
  ASSERT_EQ(over.exit_code, 0) << over.err;
  EXPECT_EQ(count_lines(over.out), 6);
}

TEST(CliContact, ConvexBodies) {
  // Spheres given as convex bodies reproduce the sphere result.
  const auto sphere = run_cli(with({"contact"}, with(ice, {"--force", "1e-3", "--json"})));
  const auto convex = run_cli(with({"contact"}, with(ice, {"--force", "1e-3", "--json",
                                                           "--curvature-radii", "1e-6,1e-6"})));
  ASSERT_EQ(convex.exit_code, 0) << convex.err;
  const auto js = nlohmann::json::parse(sphere.out);
  const auto jc = nlohmann::json::parse(convex.out);
  EXPECT_NEAR(jc["overlap"].get<double>() / js["overlap"].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(jc["ellipse"]["x0"].get<double>(), 1.0);
  const auto ellipse = run_cli(with({"contact"}, with(ice, {"--force", "1e-3", "--json", "--curvature-radii",
                                                            "1e-6,5e-6", "--angle", "0.3"})));
  ASSERT_EQ(ellipse.exit_code, 0) << ellipse.err;
  EXPECT_LT(nlohmann::json::parse(ellipse.out)["ellipse"]["x0"].get<double>(), 1.0);
}

TEST(CliContact, BadInputEachCase) {
  const std::vector<std::string> explicit_body = {"contact", "--nu", "0.3", "--density", "1000",
                                                  "--radius", "1e-6"};
  expect_rejected(with(explicit_body, {"--E", "-5"}), "--E", "-5");
  expect_rejected(with(explicit_body, {"--E", "0"}), "--E", "0");
  expect_rejected(with(explicit_body, {"--E", "nan"}), "--E", "nan");
  expect_rejected(with(explicit_body, {"--E", "abc"}), "--E", "abc");
  expect_rejected(with({"contact"}, with(ice, {"--nu", "0.5"})), "--nu", "0.5");
  expect_rejected(with({"contact"}, with(ice, {"--nu2", "-1"})), "--nu2", "-1");
  expect_rejected(with({"contact"}, with(ice, {"--density", "0"})), "--density", "0");
  expect_rejected(with({"contact"}, with(ice, {"--density2", "-3"})), "--density2", "-3");
  expect_rejected({"contact", "--material", "water-ice", "--radius", "-1e-6"}, "--radius", "-1e-6");
  expect_rejected({"contact", "--material", "water-ice", "--radius", "inf"}, "--radius", "inf");
  expect_rejected(with({"contact"}, with(ice, {"--radius2", "0"})), "--radius2", "0");
  expect_rejected(with({"contact"}, with(ice, {"--gamma", "-0.1", "--law", "jkr"})), "--gamma", "-0.1");
  expect_rejected({"contact", "--material", "unobtainium", "--radius", "1e-6"}, "--material", "unobtainium");
  expect_rejected(with({"contact"}, with(ice, {"--material2", "kryptonite"})), "--material2", "kryptonite");
  // Missing required options.
  expect_rejected({"contact", "--material", "water-ice"}, "--radius", "(not given)");
  expect_rejected({"contact", "--radius", "1e-6"}, "--E", "(not given)");
  // A law that needs gamma without one.
  expect_rejected({"contact", "--material", "ice-bshp96", "--radius", "1e-2", "--law", "jkr"}, "--gamma",
                  "(not given)");
  expect_rejected({"contact", "--material", "ceramics", "--radius", "1e-3", "--law", "maugis"}, "--gamma",
                  "(not given)");
  expect_rejected(with({"contact"}, with(ice, {"--law", "bogus"})), "--law", "bogus");
  expect_rejected(with({"contact"}, with(ice, {"--law", "jkr", "--force", "-1"})), "--force", "-1");
  expect_rejected(with({"contact"}, with(ice, {"--law", "hertz", "--overlap", "-1e-9"})), "--overlap", "-1e-9");
  expect_rejected(with({"contact"}, with(ice, {"--law", "maugis", "--z0", "0"})), "--z0", "0");
  expect_rejected(with({"contact"}, with(ice, {"--csv", "--forces", "1:0:5"})), "--forces", "1:0:5");
  // Data files: malformed, partial, out of range.
  const auto malformed = write_temp("bounce-malformed.toml", "[[material]\nname = \n");
  expect_rejected(with({"contact"}, with(ice, {"--materials-file", malformed})), malformed + ":1:12",
                  "(malformed TOML)");
  const auto partial = write_temp("bounce-partial.toml",
                                  "[[material]]\nname = \"water-ice\"\nyoungs_modulus = 7e9\n"
                                  "poisson_ratio = 0.25\n");
  expect_rejected(with({"contact"}, with(ice, {"--materials-file", partial})),
                  partial + ": water-ice.density", "(missing)");
  const auto out_of_range = write_temp("bounce-range.toml",
                                       "[[material]]\nname = \"water-ice\"\nyoungs_modulus = -7e9\n"
                                       "poisson_ratio = 0.25\ndensity = 1000.0\n");
  expect_rejected({"materials", "--materials-file", out_of_range},
                  out_of_range + ": water-ice.youngs_modulus", "-7e+09");
  expect_rejected({"materials", "--materials-file", "/nonexistent/bounce.toml"}, "--materials-file",
                  "/nonexistent/bounce.toml");
}

TEST(CliContact, UnknownOptionAndHelp) {
  const auto r = run_cli({"contact", "--frobnicate", "3"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--frobnicate"), std::string::npos);
  const auto help = run_cli({"contact", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--law"), std::string::npos);
}

// `bounce fit` from the command line (docs/fitting.md): the SPEC's JSON keys, a parameter
// recovered from the viscoelastic model's own curve, thread-independent output, and every
// bad input refused by the one rule.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "run_cli.hpp"

namespace {

using bounce::testing::expect_rejected;
using bounce::testing::run_cli;
using Args = std::vector<std::string>;

const Args ice = {"--material", "ice-bshp96", "--radius", "1e-2", "--model", "viscoelastic"};

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

Args fit(const std::string& data, const Args& more) {
  Args a = {"fit", "--data", data};
  a.insert(a.end(), ice.begin(), ice.end());
  a.insert(a.end(), more.begin(), more.end());
  return a;
}

// The viscoelastic model's own curve at A = 2e-6 s (from `bounce curve`), as a data file.
std::string curve_data(const std::string& name) {
  const auto r = run_cli({"curve", "--material", "ice-bshp96", "--radius", "1e-2", "--A", "2e-6", "--velocities",
                          "0.01:3:12", "--log", "--csv"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::string text = "# from bounce curve\nvelocity,cor\n";
  std::istringstream lines(r.out);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    const auto first = line.find(','), second = line.find(',', first + 1);
    text += line.substr(0, second) + "\n";
  }
  return write_file(name, text);
}

}  // namespace

TEST(CliFit, RecoversAFromTheModelsOwnCurveWithTheSpecKeys) {
  const std::string data = curve_data("bounce_fit_curve.csv");
  const auto r = run_cli(fit(data, {"--grid", "A=1e-8:1e-4:21", "--precision", "1e-5", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"best", "ranges", "chi2", "points"}) EXPECT_TRUE(j.contains(key)) << key;
  // Nelder-Mead to 1e-5 in log A; the data carry the curve's 17 digits.
  EXPECT_NEAR(j["best"]["A"].get<double>() / 2e-6, 1.0, 1e-4);
  EXPECT_EQ(j["points"].size(), 12U);
  EXPECT_TRUE(j.contains("characteristic_velocity"));
}

TEST(CliFit, OutputDoesNotDependOnTheThreadCount) {
  const std::string data = curve_data("bounce_fit_threads.csv");
  const auto one = run_cli(fit(data, {"--grid", "A=1e-8:1e-4:9", "--threads", "1", "--json"}));
  const auto two = run_cli(fit(data, {"--grid", "A=1e-8:1e-4:9", "--threads", "2", "--json"}));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, two.out);
}

TEST(CliFit, BadInputIsRefusedByTheOneRule) {
  const std::string good = write_file("bounce_fit_good.csv", "velocity,cor\n0.1,0.5\n1,0.4\n");
  expect_rejected({"fit", "--material", "ice-bshp96", "--radius", "1e-2"}, "--data", "(not given)");
  expect_rejected(fit("/nonexistent/x.csv", {}), "--data", "/nonexistent/x.csv");
  const std::string bad = write_file("bounce_fit_bad.csv", "velocity,cor\n0.1,0.5\n1,abc\n");
  expect_rejected(fit(bad, {}), bad + ":3: cor", "abc");
  const std::string fast = write_file("bounce_fit_fast.csv", "velocity,cor\n1e5,0.5\n");
  expect_rejected(fit(fast, {}), fast + ":2: velocity", "1e+05");
  const std::string empty = write_file("bounce_fit_empty.csv", "# nothing\nvelocity,cor\n");
  expect_rejected(fit(empty, {}), "--data", empty);
  const std::string one = write_file("bounce_fit_one.csv", "velocity,cor\n0.1,0.5\n");
  expect_rejected(fit(one, {"--fit", "A,yield"}), "--data", one);  // fewer points than parameters
  const std::string above = write_file("bounce_fit_above.csv", "velocity,cor\n0.1,0.5\n1,1.01\n");
  expect_rejected(fit(above, {}), above + ":3: cor", "1.01");
  const std::string unknown = write_file("bounce_fit_unknown.csv", "velocity,cor,angle\n0.1,0.5,3\n");
  expect_rejected(fit(unknown, {}), unknown + ":1: header", "angle");
  const std::string missing = write_file("bounce_fit_missing.csv", "velocity\n0.1\n");
  expect_rejected(fit(missing, {}), missing + ":1: header", "velocity");
  expect_rejected(fit(good, {"--fit", "A,gamma"}), "--fit", "A,gamma");
  expect_rejected(fit(good, {"--fit", "A,A"}), "--fit", "A,A");
  expect_rejected(fit(good, {"--grid", "A=1e-3:1e-6:5"}), "--grid", "A=1e-3:1e-6:5");
  expect_rejected(fit(good, {"--grid", "A=0:1:5"}), "--grid", "A=0:1:5");
  expect_rejected(fit(good, {"--grid", "tvis=1e-12:1e-9:5"}), "--grid", "tvis=1e-12:1e-9:5");
  expect_rejected(fit(good, {"--A", "1e-6"}), "--A", "1e-6");
  // 1e10 grid points would exhaust the memory before the first collision.
  const std::string psl = write_file("bounce_fit_psl.csv", "velocity,cor\n1,0.5\n2,0.6\n3,0.7\n");
  expect_rejected({"fit", "--data", psl, "--material", "psl", "--radius", "1e-6", "--fit", "gamma,tvis", "--grid",
                   "gamma=0.01:1:100000,tvis=1e-12:1e-10:100000"},
                  "--grid", "1e+10 points (1e+10 with the yield axis)");
  expect_rejected(fit(good, {"--threads", "-1"}), "--threads", "-1");
  expect_rejected(fit(good, {"--precision", "0"}), "--precision", "0");
  expect_rejected({"fit", "--data", good, "--material", "ice-bshp96", "--radius", "1e-2", "--model", "power-law"},
                  "--model", "power-law");
  expect_rejected(fit(good, {"--friction", "0.3"}), "--friction", "0.3");
}

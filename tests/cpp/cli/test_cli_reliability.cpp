// What a new user's probe found (reliability round 2): each row's command, as the user typed
// it, gives the behaviour docs/cli.md and docs/fitting.md state.
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "run_cli.hpp"

namespace {

using bounce::testing::count_lines;
using bounce::testing::expect_rejected;
using bounce::testing::run_cli;
using Args = std::vector<std::string>;

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

const std::string source = BOUNCE_SOURCE_DIR;
const Args psl_quartz = {"--data",  source + "/data/experiments/synthetic-psl-quartz.csv",
                         "--material", "psl", "--radius", "0.635e-6", "--wall", "--material2", "quartz"};
const Args acrylic = {"--data", source + "/data/experiments/synthetic-acrylic-spheres.csv", "--material", "acrylic",
                      "--radius", "1.98e-3", "--model", "viscoelastic", "--A", "1e-9"};

Args with(Args a, const Args& more) {
  a.insert(a.end(), more.begin(), more.end());
  return a;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// Row 1: a trajectory followed for 1000 s ran out of memory (exit 4); now it is thinned in time
// to at most dynamics::max_trajectory_rows rows, and a note on stderr says so.
TEST(CliReliability, LongTrajectoryIsBounded) {
  const auto r = run_cli({"collide", "--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis",
                          "1e-11", "--velocity", "1", "--follow", "1e3", "--trajectory", "--csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LE(count_lines(r.out), 200001);
  EXPECT_TRUE(has(r.err, "bounce: note: the trajectory reached the bound of 200000 rows")) << r.err;
}

// Row 9: N = 1e3 is an integer.
TEST(CliReliability, PointCountInExponentForm) {
  const auto r = run_cli({"curve", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--velocities",
                          "1:10:1e3", "--csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_lines(r.out), 1001);
  expect_rejected({"curve", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--velocities", "1:10:2.5"},
                  "--velocities", "1:10:2.5");
}

// Row 3: --chi2-grid has no text form (refused); --timing is printed in text too.
TEST(CliReliability, FitOptionsAreNotIgnoredInText) {
  const Args grid = {"--fit", "yield", "--grid", "yield=1e7:1e9:5"};
  expect_rejected(with(with({"fit"}, acrylic), with(grid, {"--chi2-grid"})), "--chi2-grid", "given");
  const auto r = run_cli(with(with({"fit"}, acrylic), with(grid, {"--timing"})));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "timing:")) << r.out;
}

// Row 4: the best value on its grid's edge, off it by round-off, is warned about.
TEST(CliReliability, EdgeWarningSurvivesRoundOff) {
  const auto r = run_cli(with(with({"fit"}, psl_quartz),
                              {"--fit", "gamma,tvis", "--grid", "gamma=0.001:0.01:5,tvis=1e-13:1e-11:5", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::string warnings = j.at("warnings").dump();
  EXPECT_TRUE(has(warnings, "the best gamma lies on the edge of its grid")) << warnings;
  EXPECT_TRUE(has(warnings, "the best tvis lies on the edge of its grid")) << warnings;
}

// Row 11: a yield strength no measured speed reaches is a lower limit with a warning, the same
// whatever the grid's density; text mode prints it.
TEST(CliReliability, UndeterminedYieldIsALowerLimit) {
  std::vector<double> limits;
  for (const char* n : {"5", "50"}) {
    const auto r = run_cli(with(with({"fit"}, acrylic), {"--fit", "yield", "--grid", std::string("yield=1e9:1e11:") + n, "--json"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j.at("best").at("yield").is_null());
    limits.push_back(j.at("lower_limits").at("yield").get<double>());
    EXPECT_TRUE(has(j.at("warnings").dump(), "yield is not determined")) << j.at("warnings").dump();
  }
  EXPECT_DOUBLE_EQ(limits[0], limits[1]);
  const auto text = run_cli(with(with({"fit"}, acrylic), {"--fit", "yield", "--grid", "yield=1e9:1e11:5"}));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_TRUE(has(text.out, "yield    >= ")) << text.out;
}

// Row 17: as many parameters as points: the fit need not pass through them.
TEST(CliReliability, AsManyParametersAsPointsWording) {
  const std::string data = write_file("bounce-three-points.csv", "velocity,cor\n1,0.9\n2,0.8\n3,0.7\n");
  const auto r = run_cli({"fit", "--data", data, "--material", "ice-bshp96", "--radius", "0.01", "--model",
                          "viscoelastic", "--fit", "A,yield", "--grid", "A=1e-8:1e-4:5,yield=1e7:1e11:5", "--grid-only",
                          "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string w = nlohmann::json::parse(r.out).at("warnings").dump();
  EXPECT_FALSE(has(w, "passes through every point")) << w;
}

// Row 5: a loaded table with a COR outside [0, 1] is refused; row 8: a file that is not a
// table is named as typed, in our words.
TEST(CliReliability, LoadedTablesAreChecked) {
  const auto made = run_cli({"table", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--velocities",
                             "0.01:10", "--json"});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  auto j = nlohmann::json::parse(made.out);
  j["nodes"][1][1] = 7.0;
  const std::string edited = write_file("bounce-edited-table.json", j.dump());
  const auto r = run_cli({"table", "--load", edited, "--velocity", "1"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "0 <= cor <= 1")) << r.err;
  const std::string garbage = write_file("bounce-garbage.csv", "garbage,1\n");
  const auto g = run_cli({"table", "--load", garbage, "--velocity", "1"});
  EXPECT_EQ(g.exit_code, 2);
  EXPECT_TRUE(has(g.err, "--load = " + garbage + " is invalid")) << g.err;
  EXPECT_FALSE(has(g.err, "json.exception")) << g.err;
  const std::string bad = write_file("bounce-bad.json", "{bad");
  const auto b = run_cli({"rules", "--material", "quartz", "--radius", "1e-6", "--input", bad});
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_TRUE(has(b.err, "line 1, column 2")) << b.err;
  EXPECT_FALSE(has(b.err, "json.exception")) << b.err;
}

// Row 10: sticking without a model names the model first.
TEST(CliReliability, StickingWithoutModelNamesTheModel) {
  expect_rejected({"sticking", "--material", "quartz", "--radius", "1e-6", "--wall"}, "--model", "(not given)");
}

// Rows 16 and 18: a batch's misspelt key lists only the keys a batch takes; a number in quotes is
// refused as in a materials file.
TEST(CliReliability, BatchManifestRules) {
  const std::string data = source + "/data/experiments/synthetic-psl-quartz.csv";
  const std::string misspelt =
      write_file("bounce-misspelt.toml", "[[experiment]]\ndata = \"" + data + "\"\nmaterial = \"psl\"\nradiuss = 1e-6\n");
  const auto r = run_cli({"fit", "--batch", misspelt});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "radiuss")) << r.err;
  for (const char* refused : {"compare", "chi2_grid", "timing"}) EXPECT_FALSE(has(r.err, refused)) << r.err;
  const std::string quoted =
      write_file("bounce-quoted.toml", "[[experiment]]\ndata = \"" + data + "\"\nmaterial = \"psl\"\nradius = \"0.635e-6\"\n");
  const auto q = run_cli({"fit", "--batch", quoted});
  EXPECT_EQ(q.exit_code, 2);
  EXPECT_TRUE(has(q.err, "a TOML number without quotes")) << q.err;
}

// Row 7: the data files of real instruments and spreadsheets; --columns; the columns in --help.
TEST(CliReliability, FitReadsRealDataFiles) {
  const Args fit = {"--material", "ice-bshp96", "--radius", "0.01", "--model", "viscoelastic", "--fit", "A",
                    "--grid", "A=1e-8:1e-4:5", "--grid-only", "--json"};
  const std::string plain = write_file("bounce-plain.csv", "velocity,cor\n0.01,0.9\n0.1,0.8\n1,0.6\n");
  const std::string excel = write_file("bounce-excel.csv", "\xEF\xBB\xBF\"Velocity [m/s]\";\"COR\"\n0,01;0,9\n0,1;0,8\n1;0,6\n");
  const std::string named = write_file("bounce-named.tsv", "Speed (m/s)\te\n0.01\t0.9\n0.1\t0.8\n1\t0.6\n");
  const auto a = run_cli(with({"fit", "--data", plain}, fit));
  const auto b = run_cli(with({"fit", "--data", excel}, fit));
  const auto c = run_cli(with({"fit", "--data", named, "--columns", "velocity=speed,cor=e"}, fit));
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const auto chi2 = [](const std::string& out) { return nlohmann::json::parse(out).at("chi2").get<double>(); };
  EXPECT_EQ(chi2(a.out), chi2(b.out));
  EXPECT_EQ(chi2(a.out), chi2(c.out));
  expect_rejected(with({"fit", "--data", plain, "--columns", "speed=v"}, fit), "--columns", "speed=v");
  const auto help = run_cli({"fit", "--help"});
  EXPECT_TRUE(has(help.out, "velocity [m/s], cor and optionally")) << help.out;
  EXPECT_TRUE(has(help.out, "--columns")) << help.out;
}

// Row 13: the refinement after the grid reports progress too.
TEST(CliReliability, FitProgressCoversTheRefinement) {
  const auto r = run_cli(with(with({"fit"}, psl_quartz),
                              {"--fit", "gamma,tvis", "--grid", "gamma=0.01:0.2:4,tvis=1e-13:1e-10:4", "--progress"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto grid_done = r.err.find("(100%)");
  ASSERT_NE(grid_done, std::string::npos) << r.err;
  EXPECT_NE(r.err.find("refining", grid_done), std::string::npos) << r.err;
}

// Row 19: an elliptic contact's text shows its curvatures, not the spheres' R_eff.
TEST(CliReliability, EllipseTextShowsCurvatures) {
  const auto r = run_cli({"contact", "--material", "steel", "--radius", "1e-3", "--curvature-radii", "1e-3,5e-3",
                          "--angle", "0.3", "--force", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(has(r.out, "R_eff = 0.0005 m")) << r.out;
  EXPECT_TRUE(has(r.out, "curvatures B1 = ")) << r.out;
}

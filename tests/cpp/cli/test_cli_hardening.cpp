// The hardening issue's table, row by row: every bad or extreme input is refused by the one
// rule (exit 2, one line naming what the user typed), answered, or refused as not computable
// (exit 3) — never exit 4, never a NaN or an infinity on stdout (docs/cli.md).
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "run_cli.hpp"

namespace {

using bounce::testing::count_lines;
using bounce::testing::expect_rejected;
using bounce::testing::run_cli;
using Args = std::vector<std::string>;

const Args ice = {"--material", "water-ice", "--radius", "1e-3"};
const Args ice_micron = {"--material", "water-ice", "--radius", "1e-6"};

Args with(Args base, const Args& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

Args cmd(const std::string& command, const Args& body, const Args& more) {
  return with(with({command}, body), more);
}

// A number printed as nan or inf, in any spelling a formatter uses.
bool has_non_finite(const std::string& text) {
  static const std::regex non_finite(R"((^|[^A-Za-z_])[-+]?(nan|inf)($|[^A-Za-z_]))", std::regex::icase);
  return std::regex_search(text, non_finite);
}

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

TEST(CliHardening, HugeRangeCountsAreRefusedNamingTheOption) {
  expect_rejected(cmd("curve", ice, {"--A", "1e-6", "--velocities", "1:2:99999999999999999999"}), "--velocities",
                  "1:2:99999999999999999999");
  expect_rejected(cmd("contact", ice, {"--law", "jkr", "--forces", "1:2:99999999999999999999", "--csv"}), "--forces",
                  "1:2:99999999999999999999");
  expect_rejected(cmd("sticking", {"--material", "water-ice"}, {"--model", "krijt", "--tvis", "1e-11", "--radii",
                                                                "1e-6:1e-5:99999999999999999999"}),
                  "--radii", "1e-6:1e-5:99999999999999999999");
}

TEST(CliHardening, MaugisAtTinyZ0IsTheJkrLimitOrARefusal) {
  // z0 below a femtometre has no physical meaning and is refused (it overflowed Tabor's parameter).
  expect_rejected(cmd("contact", ice_micron, {"--law", "maugis", "--z0", "1e-150"}), "--z0", "1e-150");
  expect_rejected(cmd("contact", ice_micron, {"--law", "maugis", "--z0", "1e-100"}), "--z0", "1e-100");
  // At the smallest z0 (lambda = 2e6) the Maugis-Dugdale pull-off is JKR's: -(3/2) pi gamma R_eff
  // (K13 (6)) to 1e-9 (the MD correction falls as lambda^-2, ~1e-13 here; 1e-9 leaves room for
  // the root finders' 1e-15).
  const auto r = run_cli(cmd("contact", ice_micron, {"--law", "maugis", "--z0", "1e-15", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double pull_off = nlohmann::json::parse(r.out)["pull_off_force"].get<double>();
  const double jkr = -1.5 * M_PI * 0.37 * 0.5e-6;
  EXPECT_NEAR(pull_off / jkr, 1.0, 1e-9);
}

TEST(CliHardening, RulesInputFilesAndFields) {
  const Args body = {"--material", "water-ice", "--radius", "1e-3", "--A", "1e-6"};
  expect_rejected(cmd("rules", body, {"--input", std::filesystem::temp_directory_path().string()}), "--input",
                  std::filesystem::temp_directory_path().string());
  const std::string head = R"({"normal": [1, 0, 0], "grain1": {"velocity": [-1, 0.5, 0]}, "grain2": {"velocity": [0, 0, 0]})";
  for (const std::string bad : {R"("x")", "null", "50", "-1.5"}) {
    const std::string path = write_file("bounce-rules-bad.json", head + R"(, "cor": 0.5, "cor_tangential": )" + bad + "}");
    expect_rejected(cmd("rules", body, {"--input", path}), path + ": cor_tangential", bad);
  }
  // A number beyond double precision (the fuzzer's 1e400) is malformed JSON for bounce, not exit 4.
  const std::string huge = write_file("bounce-rules-huge.json",
                                      R"({"normal": [1e400, 0, 0], "grain1": {"velocity": [-1, 0, 0]}, "grain2": {"velocity": [0, 0, 0]}, "cor": 0.5})");
  expect_rejected(cmd("rules", body, {"--input", huge}), "--input", huge);
  // eps^T given without eps^N: used, with the model's eps^N.
  const std::string path = write_file("bounce-rules-et.json", head + R"(, "cor_tangential": 0.25})");
  const auto r = run_cli(cmd("rules", body, {"--input", path}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  EXPECT_EQ(out["cor_tangential"].get<double>(), 0.25);
  EXPECT_GT(out["cor"].get<double>(), 0.0);
  EXPECT_LT(out["energy_change"].get<double>(), 0.0);
}

TEST(CliHardening, RulesAtAnExtremelySlowApproachFollowCollidesRule) {
  // The same rule as `collide --velocity 1e-300`: an impact energy below double precision is
  // refused, naming the file's encounter.
  const std::string path = write_file(
      "bounce-rules-slow.json", R"({"normal": [1, 0, 0], "grain1": {"velocity": [-1e-300, 0, 0]}, "grain2": {"velocity": [0, 0, 0]}})");
  expect_rejected({"rules", "--material", "water-ice", "--radius", "1e-3", "--A", "1e-6", "--input", path},
                  path + ": velocity", "1e-300");
  expect_rejected({"collide", "--material", "water-ice", "--radius", "1e-3", "--A", "1e-6", "--velocity", "1e-300"},
                  "--velocity", "1e-300");
  // At 1e-9 m/s the model's own e^N (just below 1) is used and is <= 1.
  const std::string slow = write_file(
      "bounce-rules-slow.json", R"({"normal": [1, 0, 0], "grain1": {"velocity": [-1e-9, 0, 0]}, "grain2": {"velocity": [0, 0, 0]}})");
  const auto r = run_cli({"rules", "--material", "water-ice", "--radius", "1e-3", "--A", "1e-6", "--input", slow});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LE(nlohmann::json::parse(r.out)["cor"].get<double>(), 1.0);
}

TEST(CliHardening, ElasticCollisionsDoNotCreateEnergy) {
  for (const std::string method : {"master", "integrate"}) {
    for (const Args& model : {Args{"--model", "hertz"}, Args{"--A", "0"}, Args{"--eta1", "0", "--eta2", "0"}}) {
      const auto r = run_cli(cmd("collide", ice, with(model, {"--velocity", "1", "--json", "--method", method})));
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const auto out = nlohmann::json::parse(r.out);
      // A passive force gives e <= 1 exactly (integration error is rounded to the bound).
      EXPECT_LE(out["cor"].get<double>(), 1.0) << method;
      EXPECT_GE(out["energy"]["bulk_dissipated"].get<double>(), 0.0) << method;
    }
  }
}

TEST(CliHardening, SurfaceEnergiesBeyondAnySolidAreRefused) {
  // gamma = 1e300 overflowed BP04's W0 inside a warning's text (found by the CLI fuzzer).
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity", "2", "--gamma=1e300", "--json"}), "--gamma", "1e300");
}

TEST(CliHardening, InfiniteRadiusIsNotAWall) {
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity", "1", "--radius2", "inf"}), "--radius2", "inf");
}

TEST(CliHardening, ExtremeValuesNeverPrintNanOrInf) {
  const std::vector<Args> calls = {
      {"contact", "--law", "hertz", "--material", "water-ice", "--radius", "1e308", "--overlap", "1e-6"},
      {"contact", "--law", "hertz", "--radius", "1e-3", "--E", "1e-300", "--nu", "0.3", "--density", "1000",
       "--overlap", "1e-6"},
      {"collide", "--material", "water-ice", "--radius", "1e-3", "--A", "1e-6", "--velocity", "1e308"},
      {"collide", "--model", "krijt", "--tvis", "1e-11", "--material", "water-ice", "--radius", "1e-6", "--velocity",
       "4.9e-324"},
      {"analytic", "--material", "water-ice", "--radius", "1e-3", "--A", "1e-300", "--velocity", "1"},
      {"collide", "--material", "water-ice", "--radius", "1e-3", "--A", "1e300", "--velocity", "1e300"},
  };
  for (const auto& call : calls) {
    for (const bool json : {false, true}) {
      const auto r = run_cli(json ? with(call, {"--json"}) : call);
      SCOPED_TRACE(::testing::PrintToString(call));
      EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 2 || r.exit_code == 3) << r.exit_code << r.err;
      EXPECT_FALSE(has_non_finite(r.out)) << r.out;
      if (r.exit_code != 0) {
        EXPECT_EQ(count_lines(r.err), 1) << r.err;
      }
    }
  }
}

TEST(CliHardening, ContradictoryOrUnusedOptionsAreRefused) {
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity", "1", "--csv", "--json"}), "--csv", "given");
  expect_rejected(cmd("curve", ice, {"--A", "1e-6", "--velocities", "1:2:3", "--velocity", "5"}), "--velocity", "5");
  expect_rejected(cmd("sticking", ice, {"--model", "krijt", "--tvis", "1e-11", "--radii", "1e-6:1e-5:3"}), "--radius",
                  "1e-3");
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity", "1", "--z0", "1e-10"}), "--z0", "1e-10");
  expect_rejected(cmd("analytic", ice, {"--A", "1e-6", "--velocity", "1", "--yield", "1e7"}), "--yield", "1e7");
  expect_rejected(cmd("table", ice, {"--A", "1e-6", "--json", "--velocity", "1"}), "--velocity", "1");
  expect_rejected(cmd("table", ice, {"--A", "1e-6", "--velocities", "1:2", "--json", "--c-header", "x"}),
                  "--c-header", "x");
  expect_rejected(cmd("table", ice, {"--A", "1e-6", "--velocities", "1:2"}), "output format", "(none given)");
  expect_rejected(cmd("contact", ice, {"--forces", "1:2:3"}), "--forces", "1:2:3");
  expect_rejected(cmd("contact", ice, {"--overlaps", "1e-9:1e-8:3"}), "--overlaps", "1e-9:1e-8:3");
  expect_rejected(cmd("contact", ice, {"--contact-radii", "1e-6:1e-5:3"}), "--contact-radii", "1e-6:1e-5:3");
  // A point of a range that the law refuses names the range, not --force.
  expect_rejected(cmd("contact", ice, {"--law", "dmt", "--csv", "--forces", "-1:1:3"}), "--forces", "-1:1:3");
  // LO = HI: N equal points (the fuzzer's 3:3:127 gave a decreasing range).
  const auto same = run_cli(cmd("contact", ice, {"--csv", "--overlaps", "3e-9:3e-9:127"}));
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(count_lines(same.out), 128);
}

// A value is quoted as the user typed it, also where the library checks it after binding (the
// sound speed needs the pair; docs/architecture.md, values as typed): 1e5, not 1e+05.
TEST(CliHardening, ValuesAreQuotedAsTyped) {
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity", "1e5"}), "--velocity", "1e5");
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--tvis", "1.0e-6", "--velocity", "1"}), "--tvis", "1.0e-6");
  expect_rejected(cmd("collide", {"--material", "water-ice", "--radius", "1e-8"},
                      {"--model", "maugis-viscoelastic", "--tvis", "1e-11", "--z0", "0.1e-7", "--velocity", "1"}),
                  "--z0", "0.1e-7");
}

TEST(CliHardening, ParserErrorsFollowTheOneLineRule) {
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity", "1", "--velocity", "2"}), "--velocity", "1, 2");
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity=1", "--velocity", "2"}), "--velocity", "1, 2");
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity", "1", "--json", "--json"}), "--json",
                  "(given), (given)");
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity", "1", "--tolerance", "abc"}), "--tolerance", "abc");
  expect_rejected(cmd("collide", ice, {"--A", "1e-6", "--velocity"}), "--velocity", "(no value)");
  expect_rejected({"foo"}, "command", "foo");
  const auto r = run_cli({"foo"});
  EXPECT_NE(r.err.find("collide"), std::string::npos) << r.err;  // the commands are listed
}

TEST(CliHardening, MessagesNameWhatTheUserTyped) {
  expect_rejected(cmd("contact", {"--radius", "1e-6", "--material", ""}, {}), "--material", "\"\"");
  expect_rejected(cmd("contact", {"--radius", "1e308", "--material", "water-ice"}, {"--json"}), "--radius", "1e308");
  const auto r = run_cli(cmd("collide", ice, {"--model", "power-law", "--power-d1", "-1", "--power-d2", "1",
                                              "--power-alpha", "1", "--velocity", "1"}));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.find("> 0 > 0"), std::string::npos) << r.err;
}

TEST(CliHardening, WriteErrorsAreErrors) {
  const std::string command = std::string(BOUNCE_CLI) + " collide --material water-ice --radius 1e-3 --A 1e-6 "
                              "--velocity 1 > /dev/full 2>/dev/null";
  const int status = std::system(command.c_str());
  EXPECT_NE(WEXITSTATUS(status), 0);
}

TEST(CliHardening, MaterialsFilesThatAreNotTables) {
  const Args call = cmd("collide", ice, {"--A", "1e-6", "--velocity", "1", "--materials-file"});
  expect_rejected(with(call, {""}), "--materials-file", "\"\"");
  const std::string dir = std::filesystem::temp_directory_path().string();
  expect_rejected(with(call, {dir}), "--materials-file", dir);
  const std::string both = write_file("bounce-both.toml",
                                      "[[material]]\nname = \"water-ice\"\nyoungs_modulus = 7e9\npoisson_ratio = 0.25\n"
                                      "density = 1000.0\nsurface_energy = 0.37\nsurface_energy_range = [0.1, 0.4]\n");
  expect_rejected(with(call, {both}), both + ": water-ice.surface_energy_range", "(given with surface_energy)");
}

TEST(CliHardening, StickingAtEverySpeedIsAResult) {
  for (const Args& more : {Args{"--tvis", "1e-6"}, Args{"--tvis", "1e-11", "--yield", "1e7"}}) {
    const auto r = run_cli(cmd("sticking", ice_micron, with({"--model", "krijt", "--json"}, more)));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto out = nlohmann::json::parse(r.out);
    EXPECT_TRUE(out["sticking_velocity"].is_null());
    EXPECT_NE(out["note"].get<std::string>().find("every speed up to the transversal sound speed"), std::string::npos);
  }
  // A surface energy so small that the threshold underflows: refused as not computable, saying why.
  const auto r = run_cli(cmd("sticking", ice_micron, {"--model", "krijt", "--tvis", "1e-11", "--gamma", "1e-300"}));
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("outside double precision"), std::string::npos) << r.err;
}

TEST(CliHardening, KrijtWithATinyFollowTimeIsAResult) {
  const auto r = run_cli(cmd("collide", ice_micron, {"--model", "krijt", "--tvis", "1e-11", "--velocity", "1",
                                                     "--follow", "1e-12", "--json"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(has_non_finite(r.out));
}

TEST(CliHardening, CsvOutputsReportWarningsOnStderr) {
  // A 1 m sphere at 1000 m/s: strains far from small, near the sound speed.
  const Args big = {"--material", "water-ice", "--radius", "1", "--A", "1e-6"};
  const auto curve = run_cli(cmd("curve", big, {"--velocities", "1:1000:3"}));
  ASSERT_EQ(curve.exit_code, 0) << curve.err;
  EXPECT_NE(curve.err.find("bounce: warning: at velocity 1000: contact radius / R_eff"), std::string::npos) << curve.err;
  const auto table = run_cli(cmd("table", big, {"--velocities", "1:1000", "--csv"}));
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.err.find("bounce: warning: contact radius / R_eff"), std::string::npos) << table.err;
}

TEST(CliHardening, TableProgressHasTrueTotals) {
  const auto r = run_cli(cmd("table", ice, {"--A", "1e-6", "--velocities", "0.1:10", "--csv", "--progress"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // An adaptive table does not know its size in advance: counts as it goes, then done/done.
  const std::regex last(R"(bounce table: (\d+)/(\d+) \(100%\))");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, last)) << r.err;
  EXPECT_EQ(m[1].str(), m[2].str());
  EXPECT_EQ(r.err.find("/2000"), std::string::npos) << r.err;
}

}  // namespace

namespace {

TEST(CliHardening, RefusalsComeFastAndSayWhatToDo) {
  // An overdamped contact integrated directly creeps apart without end: the step budget
  // (2e6 steps, ~0.5 s) ends it with a pointer to the master curve, not after 10-40 s.
  const auto creep = run_cli({"collide", "--material", "water-ice", "--radius", "1e-3", "--A", "1", "--velocity", "1",
                              "--method", "integrate"});
  EXPECT_EQ(creep.exit_code, 3);
  EXPECT_NE(creep.err.find("--method master"), std::string::npos) << creep.err;
  // K13's initial condition needs k < 0.995; k outside [1e-12, 0.99] is bad input, not a solver failure.
  expect_rejected({"collide", "--model", "krijt", "--tvis", "1e-11", "--material", "water-ice", "--radius", "1e-6",
                   "--velocity", "1", "--k", "0.999"},
                  "--k", "0.999");
  expect_rejected({"collide", "--model", "krijt", "--tvis", "1e-11", "--material", "water-ice", "--radius", "1e-6",
                   "--velocity", "1", "--k", "1e-15"},
                  "--k", "1e-15");
}

}  // namespace

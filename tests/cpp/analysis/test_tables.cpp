// eps^N tables (docs/tables.md): the stated interpolation error against direct evaluation
// at 1e4 random speeds, JSON round trip, the C header compiled standalone and agreeing with
// the library, and bad input.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "model_helpers.hpp"
#include <nlohmann/json.hpp>

#include "bounce/analysis/tables.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/materials_table.hpp"
#include "cli/run_cli.hpp"

using namespace bounce;
using namespace bounce::analysis;

namespace {

Pair bshp96() { return Pair::identical(MaterialTable::builtin().at("ice-bshp96"), 0.01); }

models::Model viscoelastic() { return bounce::testing::viscoelastic(bshp96(), 1e-6); }

// K13 §3-like: 1 um water-ice grains, crack law, T_vis = 1e-11 s (sticks below ~4.2 m/s).
Pair k13() { return Pair::identical(MaterialTable::builtin().at("water-ice"), 1e-6); }
models::Model krijt() { return bounce::testing::model(k13(), "krijt", {{"tvis", 1e-11}}); }

// The largest |table - direct| over n log-uniform random speeds in [lo, hi], and the
// number of outcomes that differ.
struct Check {
  double worst = 0.0;
  int outcome_mismatches = 0;
};
Check check(const NormalTable& t, const Pair& pair, const models::Model& model, const CollideOptions& o, int n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(std::log(t.g_min), std::log(t.g_max));
  Check c;
  for (int i = 0; i < n; ++i) {
    const double g = std::exp(u(rng));
    const auto direct = collide(pair, model, g, o);
    c.worst = std::max(c.worst, std::abs(t.cor(g) - direct.cor));
    c.outcome_mismatches += t.outcome(g) != direct.outcome;
  }
  return c;
}

}  // namespace

// Direct integration (not the master curve) so that the table is checked against the
// function it was built from, with its integration noise (~1e-10, far below the bound).
TEST(Tables, ViscoelasticWithinBoundAtRandomSpeeds) {
  CollideOptions o;
  o.method = Method::integrate;
  const NormalTable t = build_normal_table(bshp96(), viscoelastic(), 1e-4, 100.0, o);
  EXPECT_EQ(t.sticking_velocity, 0.0);
  const Check c = check(t, bshp96(), viscoelastic(), o, 10000);
  EXPECT_LE(c.worst, t.bound);  // the stated bound, 1e-6
  EXPECT_EQ(c.outcome_mismatches, 0);
}

// With sticking: eps^N = 0 below v_s, ~sqrt(g - v_s) just above (tabulated in ln(g - v_s)).
TEST(Tables, KrijtWithinBoundAtRandomSpeeds) {
  const NormalTable t = build_normal_table(k13(), krijt(), 0.1, 20.0);
  EXPECT_GT(t.sticking_velocity, 1.0);
  EXPECT_LT(t.sticking_velocity, 10.0);
  const Check c = check(t, k13(), krijt(), {}, 10000);
  EXPECT_LE(c.worst, t.bound);
  // Speeds within the sticking search's bracket (1e-13 relative) of v_s could differ;
  // none of 1e4 random speeds falls there.
  EXPECT_EQ(c.outcome_mismatches, 0);
}

TEST(Tables, JsonRoundTripAndCsv) {
  const NormalTable t = build_normal_table(k13(), krijt(), 0.5, 10.0);
  const NormalTable back = NormalTable::from_json(t.to_json());
  for (double g : {0.5, 1.0, t.sticking_velocity * (1 + 1e-9), 5.0, 9.99}) {
    EXPECT_EQ(back.cor(g), t.cor(g)) << g;  // %.17g survives the round trip exactly
    EXPECT_EQ(back.outcome(g), t.outcome(g)) << g;
  }
  const std::string csv = t.to_csv();
  EXPECT_EQ(csv.rfind("velocity,x,cor,slope,outcome\n", 0), 0u);
  EXPECT_EQ(bounce::testing::count_lines(csv), static_cast<int>(t.curve.x.size()) + 1);
}

// The header is C99 on its own: compiled with -std=c99 -pedantic -Werror by the C compiler
// found at configure time, its functions agree with the library to round-off (the same
// algorithm in C; 1e-14 relative allows a different evaluation order of the Hermite sum).
TEST(Tables, CHeaderCompilesStandaloneAndAgrees) {
  namespace fs = std::filesystem;
  const NormalTable t = build_normal_table(k13(), krijt(), 0.5, 10.0);
  const fs::path dir = fs::temp_directory_path() / ("bounce-cheader-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "k13_table.h") << t.to_c_header("k13");
  const std::vector<double> speeds = {0.5, 1.0, 3.0, t.sticking_velocity * (1 + 1e-10), 4.5, 6.0, 9.5, 10.0};
  std::string main = "#include <stdio.h>\n#include \"k13_table.h\"\nint main(void) {\n";
  for (double g : speeds) main += fmt::format("  printf(\"%.17g %d\\n\", k13_cor({0:.17g}), k13_sticks({0:.17g}));\n", g);
  main += "  printf(\"%d\\n\", k13_cor(20.0) != k13_cor(20.0));\n";
  main += "  printf(\"%d %d\\n\", k13_sticks(20.0), k13_sticks(0.1));\n  return 0;\n}\n";
  std::istringstream out(bounce::testing::compile_and_run_c99(dir, main));
  for (double g : speeds) {
    double cor = 0.0;
    int sticks = -1;
    out >> cor >> sticks;
    EXPECT_NEAR(cor, t.cor(g), 1e-14 * std::max(1.0, std::abs(t.cor(g)))) << g;
    EXPECT_EQ(sticks == 1, t.outcome(g) == dynamics::Outcome::stick) << g;
  }
  int nan_outside = 0;
  out >> nan_outside;
  EXPECT_EQ(nan_outside, 1);  // outside [g_min, g_max]: NaN, never a made-up value
  int above = 0, below = 0;
  out >> above >> below;
  EXPECT_EQ(above, -1);  // and no outcome either (it extrapolated one)
  EXPECT_EQ(below, -1);
  EXPECT_THROW((void)t.outcome(20.0), InvalidArgument);
  fs::remove_all(dir);
}

TEST(Tables, BadInput) {
  EXPECT_THROW(build_normal_table(bshp96(), viscoelastic(), 0.0, 1.0), InvalidArgument);
  EXPECT_THROW(build_normal_table(bshp96(), viscoelastic(), 1.0, 1.0), InvalidArgument);
  EXPECT_THROW(build_normal_table(bshp96(), viscoelastic(), 1.0, NAN), InvalidArgument);
  TableOptions bad;
  bad.bound = -1.0;
  EXPECT_THROW(build_normal_table(bshp96(), viscoelastic(), 0.1, 1.0, {}, bad), InvalidArgument);
  const NormalTable t = build_normal_table(bshp96(), viscoelastic(), 0.1, 1.0);
  EXPECT_THROW(t.cor(2.0), InvalidArgument);
  EXPECT_THROW(t.cor(NAN), InvalidArgument);
  EXPECT_THROW(t.to_c_header("1bad"), InvalidArgument);
  EXPECT_THROW(NormalTable::from_json("{}"), InvalidArgument);
  EXPECT_THROW(NormalTable::from_json("not json"), InvalidArgument);
}

TEST(Tables, Cli) {
  using bounce::testing::run_cli;
  const auto made = run_cli({"table", "--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis",
                             "1e-11", "--velocities", "0.5:10", "--json"});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const auto path = std::filesystem::temp_directory_path() / ("bounce-table-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << made.out;
  const auto read = run_cli({"table", "--load", path.string(), "--velocity", "7", "--json"});
  ASSERT_EQ(read.exit_code, 0) << read.err;
  const auto direct = run_cli({"collide", "--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis",
                               "1e-11", "--velocity", "7", "--json"});
  const auto a = nlohmann::json::parse(read.out), b = nlohmann::json::parse(direct.out);
  EXPECT_NEAR(a["cor"].get<double>(), b["cor"].get<double>(), 1e-6);
  EXPECT_EQ(a["outcome"], b["outcome"]);
  struct Bad {
    std::vector<std::string> args;
    std::string names;
  };
  const std::vector<Bad> bad = {
      {{"table", "--material", "steel", "--radius", "1e-3", "--velocities", "2:1", "--csv"}, "--velocities"},
      {{"table", "--material", "steel", "--radius", "1e-3", "--velocities", "1:2"}, "output format = (none given)"},
      {{"table", "--material", "steel", "--radius", "1e-3", "--velocities", "1:2", "--csv", "--bound", "0"}, "bound"},
      {{"table", "--load", path.string(), "--velocity", "20"}, "--velocity"},
      {{"table", "--load", "/nonexistent.json", "--velocity", "1"}, "--load"},
  };
  for (const auto& b2 : bad) {
    const auto r = run_cli(b2.args);
    EXPECT_EQ(r.exit_code, 2) << b2.args.back();
    EXPECT_NE(r.err.find(b2.names), std::string::npos) << r.err;
    EXPECT_EQ(bounce::testing::count_lines(r.err), 1) << r.err;
  }
  std::filesystem::remove(path);
}

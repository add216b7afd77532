// eps^T(g^N, g^T) tables (docs/tables.md): the stated error against direct integration at
// 1e4 random points over BSHP96 fig. 2's plane (all three regimes, jumps included), other
// normal models and asperity sizes, JSON round trip, the C header compiled standalone and
// agreeing with the library, and bad input.
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

// BSHP96 §III: A = 1 us, mu = sqrt(zeta0 / R_eff) (alpha = 1), the published form (the tabulated one).
ParameterInputs asperity_inputs(double zeta0_over_r, const std::string& model = "viscoelastic") {
  ParameterInputs in{{"asperity", zeta0_over_r * bshp96().effective_radius()},
                     {"friction", std::sqrt(zeta0_over_r)},
                     {"asperity_form", "published"}};
  if (model != "hertz") in["A"] = 1e-6;
  return in;
}
models::Model asperity(double zeta0_over_r, const std::string& model = "viscoelastic") {
  return bounce::testing::model(bshp96(), model, asperity_inputs(zeta0_over_r, model));
}

// Over n log-uniform random points of the table's range: the largest |table - direct|,
// and how many points had no break, one to ten, and more (the regimes the check covers).
struct Check {
  double worst = 0.0;
  int no_break = 0, few_breaks = 0, many_breaks = 0;
  int sign_changes = 0;  // points with eps^T < 0 (spin reversal)
};
Check check(const TangentialTable& t, const models::Model& model, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Check c;
  for (int i = 0; i < n; ++i) {
    const double gn = t.gn_min * std::pow(t.gn_max / t.gn_min, u(rng));
    const double gt = t.gt_min * std::pow(t.gt_max / t.gt_min, u(rng));
    CollideOptions o;
    o.tangential_velocity = gt;
    const double direct = collide(bshp96(), model, gn, o).tangential->cor;
    const double table = t.cor(gn, gt);
    c.worst = std::max(c.worst, std::abs(table - direct));
    const long breaks = t.breaks(gn, gt);
    (breaks == 0 ? c.no_break : breaks <= 10 ? c.few_breaks : c.many_breaks) += 1;
    c.sign_changes += table < 0.0;
  }
  return c;
}

}  // namespace

// The stated bound (docs/tables.md): error <= 1e-6 against direct integration at 1e4 random points.
// BSHP96 fig. 2 (b) (zeta0 = 2e-4 R_eff) over g^N 0.01-10 m/s, g^T 1e-3-1 m/s holds the
// linear-spring plateau (no break), spin reversal (eps^T < 0), the jumps where one more
// asperity breaks, and sliding with up to ~150 breaks. The points differ from the build's
// check points (another seed).
TEST(TangentialTables, WithinBoundAtRandomPoints) {
  const auto model = asperity(2e-4);
  const TangentialTable t = build_tangential_table(bshp96(), model, 0.01, 10.0, 1e-3, 1.0);
  EXPECT_LE(t.checked_error, t.bound / 4);
  const Check c = check(t, model, 10000, 7);
  EXPECT_LE(c.worst, 1e-6);
  EXPECT_GT(c.no_break, 1000);
  EXPECT_GT(c.few_breaks, 1000);
  EXPECT_GT(c.many_breaks, 1000);
  EXPECT_GT(c.sign_changes, 1000);
  RecordProperty("worst", fmt::format("{:.3g}", c.worst));
}

// Other normal models (the force jumps at contact for viscoelastic-shifted; Hertz has no
// dissipation) and fig. 2 (c)'s asperity size: fewer points, the same bound.
TEST(TangentialTables, OtherModelsAndAsperitySizes) {
  for (const auto& [model, zeta] : std::vector<std::pair<std::string, double>>{
           {"hertz", 2e-4}, {"viscoelastic-shifted", 2e-4}, {"viscoelastic", 1e-3}}) {
    const auto spec = asperity(zeta, model);
    const TangentialTable t = build_tangential_table(bshp96(), spec, 0.01, 10.0, 1e-3, 1.0);
    EXPECT_LE(check(t, spec, 1000, 11).worst, 1e-6) << model << " " << zeta;
  }
}

// docs/decisions.md D12's independent check read from the table: eps^T = -1.1331 (published form).
TEST(TangentialTables, ReproducesTheIndependentCheck) {
  const TangentialTable t = build_tangential_table(bshp96(), asperity(2e-4), 0.5, 2.0, 1e-3, 0.1);
  EXPECT_NEAR(t.cor(1.0, 0.01), -1.1331, 5e-5);  // D12 states 4 decimals
  EXPECT_EQ(t.breaks(1.0, 0.01), 0);
}

TEST(TangentialTables, JsonRoundTripAndCsv) {
  const TangentialTable t = build_tangential_table(bshp96(), asperity(1e-3), 0.1, 1.0, 1e-3, 0.3);
  const std::string json = t.to_json();
  EXPECT_TRUE(is_tangential_table(json));
  const TangentialTable u = TangentialTable::from_json(json);
  for (double gn : {0.1, 0.3, 1.0}) {
    for (double gt : {1e-3, 0.05, 0.3}) EXPECT_EQ(u.cor(gn, gt), t.cor(gn, gt));  // exact: %.17g round trip
  }
  EXPECT_EQ(u.bound, t.bound);
  EXPECT_EQ(u.check_points, t.check_points);
  const std::string csv = t.to_csv();
  EXPECT_EQ(csv.rfind("row,velocity,s,tau,y1,dy1,y2,dy2,K,dK_ds\n", 0), 0u);
  EXPECT_EQ(bounce::testing::count_lines(csv), static_cast<int>(t.row_count() * t.s.size()) + 1);
  EXPECT_FALSE(is_tangential_table(build_normal_table(bshp96(), asperity(1e-3), 0.1, 1.0).to_json()));
}

// The header is C99 on its own (the lookup is the same C file the library compiles):
// compiled with -std=c99 -pedantic -Werror, it agrees with the library to 1e-13 (the
// compilers may contract the polynomial sums differently).
TEST(TangentialTables, CHeaderCompilesStandaloneAndAgrees) {
  namespace fs = std::filesystem;
  const TangentialTable t = build_tangential_table(bshp96(), asperity(2e-4), 0.1, 3.0, 1e-3, 0.5);
  const fs::path dir = fs::temp_directory_path() / ("bounce-tt-header-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "fig2_table.h") << t.to_c_header("fig2");
  std::vector<std::pair<double, double>> points;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 20; ++i) points.emplace_back(0.1 * std::pow(30.0, u(rng)), 1e-3 * std::pow(500.0, u(rng)));
  std::string main = "#include <stdio.h>\n#include \"fig2_table.h\"\nint main(void) {\n";
  for (const auto& [gn, gt] : points) {
    main += fmt::format("  printf(\"%.17g\\n\", fig2_cor_tangential({:.17g}, {:.17g}));\n", gn, gt);
  }
  main += "  printf(\"%d %d\\n\", fig2_cor_tangential(5.0, 0.01) != fig2_cor_tangential(5.0, 0.01),\n"
          "         fig2_cor_tangential(1.0, 1.0) != fig2_cor_tangential(1.0, 1.0));\n  return 0;\n}\n";
  std::istringstream out(bounce::testing::compile_and_run_c99(dir, main));
  for (const auto& [gn, gt] : points) {
    double cor = 0.0;
    out >> cor;
    EXPECT_NEAR(cor, t.cor(gn, gt), 1e-13) << gn << " " << gt;
  }
  int nan_gn = 0, nan_gt = 0;
  out >> nan_gn >> nan_gt;
  EXPECT_EQ(nan_gn, 1);  // outside the range: NaN, never an extrapolated value
  EXPECT_EQ(nan_gt, 1);
  fs::remove_all(dir);
}

TEST(TangentialTables, BadInput) {
  auto build = [](const models::Model& m, double gt_max = 1.0) {
    return build_tangential_table(bshp96(), m, 0.01, 10.0, 1e-3, gt_max);
  };
  auto step = asperity_inputs(2e-4);
  step.erase("asperity");
  step.insert({{"tangential_law", "step"}, {"shear_damping", 100.0}});
  EXPECT_THROW(build(bounce::testing::model(bshp96(), "viscoelastic", step)), InvalidArgument);
  auto passive = asperity_inputs(2e-4);
  passive["asperity_form"] = "passive";
  EXPECT_THROW(build(bounce::testing::model(bshp96(), "viscoelastic", passive)), InvalidArgument);
  // The default form (passive since issue 40): the refusal says what to type.
  auto by_default = asperity_inputs(2e-4);
  by_default.erase("asperity_form");
  try {
    build(bounce::testing::model(bshp96(), "viscoelastic", by_default));
    ADD_FAILURE() << "a table of the default asperity form was built";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "asperity_form");
    EXPECT_EQ(e.value(), "passive");
    EXPECT_NE(e.allowed().find("passive, the default, is not tabulated): add --asperity-form published"),
              std::string::npos)
        << e.allowed();
  }
  Material sticky = MaterialTable::builtin().at("ice-bshp96");
  sticky.surface_energy = 0.1;
  const Pair sticky_pair = Pair::identical(sticky, 0.01);
  auto krijt = asperity_inputs(2e-4);
  krijt.erase("A");
  krijt["tvis"] = 1e-11;
  EXPECT_THROW(build_tangential_table(sticky_pair, bounce::testing::model(sticky_pair, "krijt", krijt), 0.01, 10.0, 1e-3, 1.0),
               InvalidArgument);
  EXPECT_THROW(build(bounce::testing::viscoelastic(bshp96(), 1e-6)), InvalidArgument);  // no friction
  // Dense breaking: the direct integration averages the sawtooth there.
  EXPECT_THROW(build(asperity(2e-4), 100.0), InvalidArgument);
  EXPECT_THROW(build_tangential_table(bshp96(), asperity(2e-4), 0.01, 10.0, 1.0, 1.0), InvalidArgument);
  EXPECT_THROW(build_tangential_table(bshp96(), asperity(2e-4), 0.0, 10.0, 1e-3, 1.0), InvalidArgument);
  const TangentialTable t = build_tangential_table(bshp96(), asperity(1e-3), 0.1, 1.0, 1e-3, 0.3);
  EXPECT_THROW(t.cor(2.0, 0.01), InvalidArgument);
  EXPECT_THROW(t.cor(0.5, 1.0), InvalidArgument);
  EXPECT_THROW(t.cor(NAN, 0.01), InvalidArgument);
  EXPECT_THROW(t.to_c_header("1bad"), InvalidArgument);
  EXPECT_THROW(TangentialTable::from_json("{}"), InvalidArgument);
  EXPECT_THROW(TangentialTable::from_json("not json"), InvalidArgument);
  auto j = nlohmann::json::parse(t.to_json());
  j["nodes"].erase(j["nodes"].begin());
  EXPECT_THROW(TangentialTable::from_json(j.dump()), InvalidArgument);  // inconsistent sizes
}

TEST(TangentialTables, Cli) {
  using bounce::testing::run_cli;
  const std::vector<std::string> pair = {"--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6",
                                         "--friction", "0.014142", "--asperity", "1e-6", "--asperity-form", "published"};
  auto with = [&pair](std::vector<std::string> args) {
    args.insert(args.begin() + 1, pair.begin(), pair.end());
    return args;
  };
  const auto made = run_cli(with({"table", "--velocities", "0.5:2", "--tangential-velocities", "0.001:0.1", "--json"}));
  ASSERT_EQ(made.exit_code, 0) << made.err;
  const auto path = std::filesystem::temp_directory_path() / ("bounce-tt-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << made.out;
  const auto read =
      run_cli({"table", "--load", path.string(), "--velocity", "1", "--tangential-velocity", "0.05", "--json"});
  ASSERT_EQ(read.exit_code, 0) << read.err;
  const auto direct = run_cli(with({"collide", "--velocity", "1", "--tangential-velocity", "0.05", "--json"}));
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  const auto a = nlohmann::json::parse(read.out), b = nlohmann::json::parse(direct.out);
  EXPECT_NEAR(a["cor_tangential"].get<double>(), b["cor_tangential"].get<double>(), 1e-6);
  using bounce::testing::expect_rejected;
  expect_rejected(with({"table", "--velocities", "0.5:2", "--tangential-velocities", "1:0.1", "--csv"}),
                  "--tangential-velocities", "1:0.1");
  expect_rejected(with({"table", "--velocities", "0.5:2", "--tangential-velocities", "0.001:100", "--csv"}),
                  "--tangential-velocities", "0.001:100");
  expect_rejected({"table", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--friction", "0.014142",
                   "--velocities", "0.5:2", "--tangential-velocities", "0.001:0.1", "--tangential-law", "step",
                   "--shear-damping", "10", "--csv"},
                  "--tangential-law", "step");
  // The default asperity form, passive, is not tabulated: exit 2 naming --asperity-form.
  expect_rejected({"table", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--friction", "0.014142",
                   "--asperity", "1e-6", "--velocities", "0.5:2", "--tangential-velocities", "0.001:0.1", "--csv"},
                  "--asperity-form", "passive");
  expect_rejected({"table", "--load", path.string(), "--velocity", "1"}, "--tangential-velocity", "(not given)");
  expect_rejected({"table", "--load", path.string(), "--velocity", "1", "--tangential-velocity", "5"},
                  "--tangential-velocity", "5");
  std::filesystem::remove(path);
}

TEST(TangentialTable, AlteredTablesOfTheFuzzerEndQuickly) {
  // fuzz/findings/table: altered tables whose lookups replayed 1e8 asperity breaks. A y2
  // altered breaks the Wronskian and is refused; so is a g_tangential_max raised 0.1 -> 1e6
  // (9e7 breaks at g^T max: above the 1e5 a table may ask); a dK/ds altered (1e6 times) passes every
  // check of the data, and its lookups now end within the physical budget of breaks,
  // 4 tau_end / level + 64 per node (tangential_table_core.h), with a value or none.
  std::string y2;
  for (const char* name : {"tangential-corrupt-y2-slow-lookup.json", "tangential-gt-max-1e6-slow-lookup.json",
                           "tangential-corrupt-dK-slow-lookup.json", "tangential-corrupt-dK-slow-lookup-2.json"}) {
    std::ifstream file(std::string(BOUNCE_SOURCE_DIR) + "/fuzz/findings/table/" + name);
    std::stringstream text;
    text << file.rdbuf();
    ASSERT_FALSE(text.str().empty()) << name;
    if (std::string(name).find("y2") != std::string::npos || std::string(name).find("gt-max") != std::string::npos) {
      EXPECT_THROW(bounce::analysis::TangentialTable::from_json(text.str()), bounce::InvalidArgument);
      continue;
    }
    const auto t = bounce::analysis::TangentialTable::from_json(text.str());
    for (double gn : {t.gn_min, std::sqrt(t.gn_min * t.gn_max), t.gn_max}) {
      for (double gt : {t.gt_min, 0.5 * (t.gt_min + t.gt_max), t.gt_max}) {
        try {
          EXPECT_LT(t.breaks(gn, gt), 1000000) << name;  // 0 to 12 breaks here (it was 1e8)
        } catch (const bounce::Error&) {  // no value: the budget ended the lookup
        }
      }
    }
  }
}

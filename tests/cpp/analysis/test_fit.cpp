// Fitting (K13 §4, docs/fitting.md): the data format, the profile ranges, e of K13 (30)
// against analysis::collide, parameters recovered from synthetic data, the grid's minimum
// against an independent brute-force search, and results independent of the thread count.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "model_helpers.hpp"

#include "bounce/analysis/fit.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/materials_table.hpp"

using namespace bounce;
using namespace bounce::analysis;

namespace {

Pair ice_pair(double radius = 1e-2) {
  const Material ice = MaterialTable::builtin().at("ice-bshp96");
  return Pair(sphere(ice, radius), sphere(ice, radius));
}

std::vector<double> geometric(double lo, double hi, std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t j = 0; j < n; ++j) v[j] = lo * std::pow(hi / lo, static_cast<double>(j) / static_cast<double>(n - 1));
  return v;
}

// Data from the viscoelastic model itself at A0 (and Y0), with an error bar of 0.01 and, with
// `scatter`, residuals of +-scatter alternating.
Experiment synthetic(const Pair& pair, double a0, std::optional<double> y0, const std::vector<double>& speeds,
                     double scatter = 0.0) {
  Experiment e;
  e.source = "synthetic";
  const models::Model m = bounce::testing::viscoelastic(pair, a0);
  for (std::size_t n = 0; n < speeds.size(); ++n) {
    double cor = cor_with_yield(pair, speeds[n], analysis::cor(pair, m, speeds[n]), y0);
    if (cor > 0.0) cor += n % 2 == 0 ? scatter : -scatter;
    e.points.push_back({speeds[n], cor, 0.01, cor == 0.0, n + 1});
  }
  return e;
}

FitProblem viscoelastic_problem(const Pair& pair, Experiment data) {
  FitProblem p;
  p.data = std::move(data);
  p.collision_axes.push_back({"A", geometric(1e-8, 1e-4, 25)});
  p.case_at = [pair](std::span<const double> v) {
    return FitCase{pair, bounce::testing::viscoelastic(pair, v[0]), CollideOptions{}};
  };
  return p;
}

void expect_refused_at(const std::string& text, const std::string& where) {
  try {
    parse_experiment(text, "f.csv");
    FAIL() << "accepted: " << text;
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter().rfind(where, 0), 0U) << e.parameter() << " for " << text;
  }
}

}  // namespace

TEST(FitData, ReadsCommentsOutcomesAndErrors) {
  const Experiment e = parse_experiment(
      "# PSL on quartz\n\nvelocity, cor ,cor_error,outcome\n1.5,0,0.01,stick # stuck\n2,0.5,0.02,\r\n3,0.7,0.02,bounce\n",
      "f.csv");
  ASSERT_EQ(e.points.size(), 3U);
  EXPECT_TRUE(e.points[0].stuck);
  EXPECT_EQ(e.points[0].line, 4U);
  EXPECT_DOUBLE_EQ(e.points[1].cor, 0.5);
  EXPECT_DOUBLE_EQ(*e.points[2].cor_error, 0.02);
  EXPECT_TRUE(e.has_errors());
  // Columns in any order; cor = 0 without an outcome column is a sticking collision.
  const Experiment f = parse_experiment("cor,velocity\n0,1\n0.4,2\n", "g.csv");
  EXPECT_TRUE(f.points[0].stuck);
  EXPECT_DOUBLE_EQ(f.points[1].velocity, 2.0);
  EXPECT_FALSE(f.has_errors());
}

TEST(FitData, RefusesMalformedFilesNamingTheLine) {
  expect_refused_at("velocity,cor\n1,abc\n", "f.csv:2: cor");
  expect_refused_at("velocity,cor\n1,0.5,3\n", "f.csv:2");
  expect_refused_at("velocity,cor\n-1,0.5\n", "f.csv:2: velocity");
  expect_refused_at("velocity,cor\nnan,0.5\n", "f.csv:2: velocity");
  expect_refused_at("velocity,cor\n1,2\n", "f.csv:2: cor");
  expect_refused_at("velocity,cor\n1,1.0001\n", "f.csv:2: cor");
  expect_refused_at("velocity,cor\n1,-0.1\n", "f.csv:2: cor");
  expect_refused_at("velocity,cor,cor_error\n1,0.5,0\n", "f.csv:2: cor_error");
  expect_refused_at("velocity,cor,cor_error\n1,0.5,1e-300\n", "f.csv:2: cor_error");
  expect_refused_at("velocity,cor,outcome\n1,0.5,stick\n", "f.csv:2: outcome");
  expect_refused_at("velocity,cor,outcome\n1,0,bounce\n", "f.csv:2: outcome");
  expect_refused_at("velocity,cor,outcome\n1,0.2,maybe\n", "f.csv:2: outcome");
  expect_refused_at("# nothing\nspeed,cor\n1,0.5\n", "f.csv:2: header");
  expect_refused_at("velocity,velocity,cor\n", "f.csv:1: header");
  expect_refused_at("velocity\n1\n", "f.csv:1: header");
  expect_refused_at("velocity,cor\n", "data");
  expect_refused_at("# only a comment\n", "data");
}

TEST(FitRanges, InterpolatesInLogValueAndLeavesGridEdgesOpen) {
  // chi^2 linear in log10(x) on each side of x = 1: crossings of 2 are exact.
  Profile p{{0.01, 0.1, 1.0, 10.0, 100.0}, {5.0, 3.0, 1.0, 3.0, 5.0}};
  ParameterRange r = profile_range(p, 1.0, 1.0, 2.0);
  ASSERT_TRUE(r.lo && r.hi);
  EXPECT_NEAR(*r.lo, std::pow(10.0, -0.5), 1e-12);  // rounding of exp/log only
  EXPECT_NEAR(*r.hi, std::pow(10.0, 0.5), 1e-12);
  // A region that reaches the first grid value is a one-sided limit.
  r = profile_range(Profile{{1.0, 2.0, 4.0}, {1.0, 1.5, 9.0}}, 1.0, 1.0, 2.0);
  EXPECT_FALSE(r.lo);
  ASSERT_TRUE(r.hi);
  // A refined minimum between grid points counts as a sample.
  r = profile_range(Profile{{1.0, 4.0}, {9.0, 9.0}}, 2.0, 1.0, 2.0);
  ASSERT_TRUE(r.lo && r.hi);
  EXPECT_NEAR(*r.lo, 2.0 * std::pow(0.5, 1.0 / 8.0), 1e-12);
}

TEST(FitModel, PlasticCorEqualsCollideWithYield) {
  // e of K13 (30) from a stored e_A must be what `collide --yield` gives, bit for bit.
  const Pair pair = ice_pair();
  for (double y : {1e6, 3e6, 1e9}) {
    const models::Model plastic =
        bounce::testing::model(pair, "viscoelastic", {{"A", 1e-5}, {"yield", y}});
    const models::Model elastic = bounce::testing::viscoelastic(pair, 1e-5);
    for (double v : {0.01, 0.3, 3.0}) {
      EXPECT_EQ(cor_with_yield(pair, v, analysis::cor(pair, elastic, v), y), analysis::cor(pair, plastic, v))
          << "Y = " << y << ", v = " << v;
    }
  }
}

TEST(FitModel, RecoversDissipativeConstantAndYieldFromSyntheticData) {
  // Centimetre ice grains: A0 = 2 us, Y0 = 150 MPa puts the yield velocity near 1 m/s.
  const Pair pair = ice_pair();
  const double a0 = 2e-6, y0 = 1.5e8;
  FitProblem p = viscoelastic_problem(pair, synthetic(pair, a0, y0, geometric(0.01, 5.0, 20)));
  p.yield_axis = FitAxis{"yield", geometric(1e6, 1e10, 41)};
  p.precision = 1e-4;
  const FitResult r = fit(p);
  // Nelder-Mead stops within `precision` in log A; Y follows from Brent's method.
  EXPECT_NEAR(r.best.values[0] / a0, 1.0, 1e-3);
  EXPECT_NEAR(r.best.values[1] / y0, 1.0, 1e-3);
  EXPECT_LT(r.best.chi2, 1e-10);
  EXPECT_LE(r.best.chi2, r.grid_best.chi2);
  // Y costs no collisions: one per grid value of A and distinct speed, then the refinement's.
  EXPECT_EQ(r.grid_collisions, 25U * 20U);
  ASSERT_TRUE(r.weighted_best);
  for (std::size_t a = 0; a < 2; ++a) {
    ASSERT_TRUE(r.intervals[a].lo && r.intervals[a].hi) << r.names[a];
    EXPECT_LE(*r.intervals[a].lo, r.weighted_best->values[a]);
    EXPECT_GE(*r.intervals[a].hi, r.weighted_best->values[a]);
  }
}

TEST(FitModel, NoPlasticDropGivesALowerLimitOnTheYieldStrength) {
  const Pair pair = ice_pair();
  FitProblem p = viscoelastic_problem(pair, synthetic(pair, 2e-6, std::nullopt, geometric(0.01, 1.0, 12), 0.01));
  p.yield_axis = FitAxis{"yield", geometric(1e6, 1e11, 26)};
  const FitResult r = fit(p);
  ASSERT_TRUE(r.ranges[1].lo);
  EXPECT_FALSE(r.ranges[1].hi);  // K13 Fig 7's grey arrow
  ASSERT_TRUE(r.ranges[0].lo && r.ranges[0].hi);
  EXPECT_LT(*r.ranges[0].lo, 2e-6);
  EXPECT_GT(*r.ranges[0].hi, 2e-6);
}

TEST(FitGrid, MinimumEqualsABruteForceSearch) {
  // The grid's minimum and profile against chi^2 (31) computed here directly, collision by
  // collision, with repeated speeds in the data.
  const Pair pair = ice_pair();
  Experiment data = synthetic(pair, 3e-5, std::nullopt, {0.05, 0.05, 0.2, 1.0, 1.0, 2.0});
  data.points[1].cor += 0.02;
  data.points[4].cor -= 0.03;
  FitProblem p = viscoelastic_problem(pair, data);
  p.refine = false;
  p.keep_grid = true;
  const FitResult r = fit(p);
  EXPECT_EQ(r.grid_collisions, 25U * 4U);  // four distinct speeds
  double best = INFINITY;
  for (std::size_t j = 0; j < p.collision_axes[0].values.size(); ++j) {
    const models::Model m = bounce::testing::viscoelastic(pair, p.collision_axes[0].values[j]);
    double sum = 0.0;
    for (const auto& point : data.points) sum += std::pow(point.cor - analysis::cor(pair, m, point.velocity), 2);
    EXPECT_DOUBLE_EQ(r.chi2_grid[j], sum / 6.0);
    best = std::min(best, sum / 6.0);
  }
  EXPECT_DOUBLE_EQ(r.grid_best.chi2, best);
  EXPECT_EQ(r.best.values, r.grid_best.values);  // no refinement asked
}

TEST(FitGrid, ResultsDoNotDependOnTheThreadCount) {
  // The K13 model on a small grid: every number bit-identical with 1, 2 and 3 threads.
  const Material psl = MaterialTable::builtin().at("psl");
  const Pair pair(sphere(psl, 0.635e-6), wall(MaterialTable::builtin().at("quartz")));
  Experiment data;
  data.source = "threads";
  const double speeds[] = {1.0, 2.0, 4.0, 8.0};
  const double cors[] = {0.0, 0.6, 0.8, 0.85};
  for (std::size_t n = 0; n < 4; ++n) data.points.push_back({speeds[n], cors[n], std::nullopt, cors[n] == 0.0, n + 2});
  FitProblem p;
  p.data = data;
  p.collision_axes = {{"gamma", geometric(0.02, 0.1, 3)}, {"tvis", geometric(1e-12, 1e-10, 3)}};
  p.yield_axis = FitAxis{"yield", geometric(1e7, 1e9, 5)};
  p.keep_grid = true;
  p.case_at = [pair](std::span<const double> v) {
    Body b1 = pair.body1(), b2 = pair.body2();
    b1.material.surface_energy = v[0];
    b2.material.surface_energy = v[0];
    const Pair with_gamma(b1, b2);
    CollideOptions o;
    o.adhesive_tolerance = 1e-5;
    return FitCase{with_gamma, bounce::testing::model(with_gamma, "krijt", {{"tvis", v[1]}}), o};
  };
  std::vector<FitResult> runs;
  for (unsigned t : {1U, 2U, 3U}) {
    p.threads = t;
    runs.push_back(fit(p));
  }
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_EQ(runs[i].chi2_grid, runs[0].chi2_grid);
    EXPECT_EQ(runs[i].best.values, runs[0].best.values);
    EXPECT_EQ(runs[i].best.chi2, runs[0].best.chi2);
    EXPECT_EQ(runs[i].cor, runs[0].cor);
  }
}

TEST(FitGrid, PointsComputedElsewhereGiveTheSameFit) {
  // The batch's path (grid points integrated one by one, anywhere, in any order) against
  // fit()'s own: the same result, bit for bit.
  const Pair pair = ice_pair();
  Experiment data = synthetic(pair, 3e-6, 1e8, geometric(0.01, 5.0, 9), 0.01);
  FitProblem p = viscoelastic_problem(pair, data);
  p.yield_axis = FitAxis{"yield", geometric(1e6, 1e10, 17)};
  p.keep_grid = true;
  const FitResult whole = fit(p);
  // In three pieces, the last first, on one and two threads.
  const std::size_t n = grid_point_count(p);
  std::vector<GridPoint> points = integrate_grid_points(p, 0, 7);
  p.threads = 1;
  const std::vector<GridPoint> last = integrate_grid_points(p, 16, n - 16);
  p.threads = 2;
  const std::vector<GridPoint> middle = integrate_grid_points(p, 7, 9);
  points.insert(points.end(), middle.begin(), middle.end());
  points.insert(points.end(), last.begin(), last.end());
  EXPECT_THROW(integrate_grid_points(p, n - 1, 2), std::out_of_range);
  const FitResult pieces = fit(p, points);
  EXPECT_EQ(pieces.chi2_grid, whole.chi2_grid);
  EXPECT_EQ(pieces.best.values, whole.best.values);
  EXPECT_EQ(pieces.ranges[0].lo, whole.ranges[0].lo);
  EXPECT_EQ(pieces.intervals[1].hi, whole.intervals[1].hi);
  EXPECT_EQ(pieces.collisions, whole.collisions);
}

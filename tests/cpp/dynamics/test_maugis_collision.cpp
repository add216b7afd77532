// maugis-viscoelastic: collisions on the Maugis-Dugdale branch (docs/adhesive.md,
// "maugis-viscoelastic"): its JKR end against jkr-viscoelastic, its DMT end, the sticking
// velocity across the transition, the energy budget, and its DEM law against the engine.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/contact/surface_forces.hpp"
#include "bounce/pair/materials_table.hpp"
#include "model_helpers.hpp"

using namespace bounce;
using namespace bounce::analysis;
using dynamics::Outcome;

namespace {
const Material& ice() { return MaterialTable::builtin().at("water-ice"); }
// Two 1 um water-ice spheres (R_eff = 0.5 um), as the acceptance has them.
Pair ice_pair() { return Pair::identical(ice(), 1e-6); }

models::Model maugis(const Pair& pair, double z0, double a) {
  return bounce::testing::model(pair, "maugis-viscoelastic", {{"z0", z0}, {"A", a}});
}
models::Model jkr_fold(const Pair& pair, double a) {
  return bounce::testing::model(pair, "jkr-viscoelastic", {{"A", a}, {"contact_end", std::string("fold")}});
}
double lambda_of(const Pair& pair, double z0) {
  return contact::surface::maugis_parameter(pair.effective_radius(), pair.effective_modulus(), *pair.surface_energy(), z0);
}
double fraction(double part, const dynamics::CollisionOutcome& o) { return part / o.energy.initial_kinetic; }
}  // namespace

// The JKR end: at lambda ~ 1e3 (z0 = 2e-12 m) the Maugis-Dugdale curve is JKR's to ~1/lambda^2
// (docs/contact.md: pull-off error 0.164/lambda^2), so the collision is jkr-viscoelastic's with
// its contact ending at the fold. The bound 3e-3 is the acceptance's; measured 1e-4 (the snap-on
// at -h0 instead of 0 and the fold's 1/lambda^2 shift).
TEST(MaugisViscoelastic, JkrEndIsJkrViscoelasticAtTheFold) {
  const Pair pair = ice_pair();
  const double a = 1e-10;
  const models::Model m = maugis(pair, 2e-12, a);
  EXPECT_GT(lambda_of(pair, 2e-12), 900.0);
  const double v_s = sticking_velocity(pair, jkr_fold(pair, a), {}, 1e-6).velocity;
  EXPECT_NEAR(sticking_velocity(pair, m, {}, 1e-6).velocity / v_s, 1.0, 1e-3);
  for (double factor : {1.5, 4.0}) {
    const double v = factor * v_s;
    const auto md = collide(pair, m, v);
    const auto jkr = collide(pair, jkr_fold(pair, a), v);
    ASSERT_EQ(md.outcome, Outcome::bounce) << factor;
    EXPECT_NEAR(md.cor, jkr.cor, 3e-3) << factor;
  }
}

// The sticking velocity is continuous across the transition, lambda from ~100 to ~0.5 (z0 from
// 2e-11 to 4e-9 m in steps of 1.1). Measured: v_s falls from 1.920 m/s (lambda = 98) to a
// minimum of 1.348 m/s near lambda = 0.5 and rises beyond; its log-slope |d ln v_s / d ln z0| is
// at most 0.30 (lambda ~ 0.9, where the fold leaves the contact for the zone alone), so a step
// of 1.1 changes ln v_s by at most 0.30 ln 1.1 = 0.029. The bound 0.04 fails any jump above 4 %
// (krijt's old switch at k == 0.02 was 5 %).
TEST(MaugisViscoelastic, StickingVelocityContinuousOverLambda) {
  const Pair pair = ice_pair();
  double previous = 0.0, z_previous = 0.0;
  for (double z0 = 2e-11; z0 <= 4e-9; z0 *= 1.1) {
    const double v_s = sticking_velocity(pair, maugis(pair, z0, 1e-10), {}, 1e-5).velocity;
    ASSERT_GT(v_s, 0.0) << z0;
    if (previous > 0.0) {
      EXPECT_LT(std::abs(std::log(v_s / previous)), 0.04) << z_previous << " -> " << z0;
    }
    previous = v_s;
    z_previous = z0;
  }
  EXPECT_LT(lambda_of(pair, z_previous), 0.6);
  EXPECT_GT(lambda_of(pair, 2e-11), 90.0);
}

// The DMT end: the least force along the branch (the pull-off under force control) tends to
// DMT's -2 pi w R as lambda -> 0, its error falling as lambda^1.5 (docs/contact.md: bound
// 2 lambda^1.5); the DEM law's force at zero rate is sampled over the branch's overlaps. The law
// is made, as pair_coeff makes it, for the materials (a 1 m pair: the collision model's own check
// h0 <= R_eff/10 holds there) and evaluated at the 1 um pair's R_eff, where h0 reaches R_eff/5.
TEST(MaugisViscoelastic, PullOffTendsToDmt) {
  const Pair pair = ice_pair();
  const double dmt = -2.0 * std::numbers::pi * *pair.surface_energy() * pair.effective_radius();
  for (double z0 : {1e-8, 1e-7, 1e-6}) {
    const models::DemModel law =
        models::make_dem_model(Pair::identical(ice(), 1.0), "maugis-viscoelastic",
                               models::bind_model_parameters("maugis-viscoelastic", {{"z0", z0}, {"A", 0.0}}));
    const models::ContactGeometry g{pair.effective_radius(), pair.effective_mass()};
    const double from = law.normal->release_overlap(g), to = 2.0 * -from;
    double least = 0.0;
    for (int i = 0; i <= 4000; ++i) least = std::min(least, law.normal->force(g, from + (to - from) * i / 4000.0, 0.0));
    const double lambda = lambda_of(pair, z0);
    EXPECT_NEAR(least / dmt, 1.0, 2.0 * std::pow(lambda, 1.5) + 1e-3) << "lambda " << lambda;
  }
}

// Without damping the only loss is the jumps (snap-on at -h0, jump-off at the fold), whose
// energy difference vanishes toward DMT, where the curve is stable nearly everywhere: measured
// 1 - e^2 ~ lambda^5 (at 1 m/s, 1 - e = 2.8e-4, 8.9e-6 and 9.1e-8 at lambda = 0.20, 0.098 and
// 0.039, z0 = 1e-8, 2e-8 and 5e-8 m, the largest the model takes for these grains); the
// exponent is checked to 5 +- 0.25 between neighbours (the loss is the jumps' alone, all of it).
TEST(MaugisViscoelastic, DmtEndWithoutDampingNeitherSticksNorLosesEnergy) {
  const Pair pair = ice_pair();
  double previous_loss = 0.0, previous_lambda = 0.0;
  for (double z0 : {1e-8, 2e-8, 5e-8}) {
    const auto out = collide(pair, maugis(pair, z0, 0.0), 1.0);
    ASSERT_EQ(out.outcome, Outcome::bounce) << z0;
    const double loss = 1.0 - out.cor * out.cor, lambda = lambda_of(pair, z0);
    EXPECT_NEAR(fraction(out.energy.crack_dissipated, out), loss, 1e-12) << z0;
    EXPECT_EQ(out.energy.bulk_dissipated, 0.0);
    if (previous_loss > 0.0) {
      EXPECT_NEAR(std::log(previous_loss / loss) / std::log(previous_lambda / lambda), 5.0, 0.25) << z0;
    }
    previous_loss = loss;
    previous_lambda = lambda;
  }
  EXPECT_LT(previous_loss, 2e-7);
}

// The energy budget closes as krijt's does (1e-6 of the impact energy) over the transition,
// speeds that stick and bounce, and along the trajectory: U_K + U_E + U_S + U_CD + U_BD is the
// impact energy. The restitution comes from the balance; the closure compares the integrated
// rate with it (dynamics::EnergyBudget), so it measures the integration.
TEST(MaugisViscoelastic, EnergyClosure) {
  const Pair pair = ice_pair();
  for (double z0 : {2e-12, 2e-10, 2e-9, 2e-8}) {
    for (double v : {0.5, 3.0, 30.0}) {
      CollideOptions o;
      o.record_trajectory = true;
      const auto out = collide(pair, maugis(pair, z0, 1e-10), v, o);
      EXPECT_LT(std::abs(fraction(out.energy.closure_error, out)), 1e-6) << z0 << " " << v;
      for (const auto& s : out.trajectory) {
        const double total = s.kinetic + s.elastic + s.surface + s.crack_dissipated + s.bulk_dissipated;
        ASSERT_NEAR(total / out.energy.initial_kinetic, 1.0, 1e-6) << z0 << " " << v << " t=" << s.time;
      }
    }
  }
}

// A slow impact on a long-range zone (1 um ice at 0.01 m/s, z0 = 50 nm): the attraction gives
// the pair ~6e5 times the impact energy, and the rate at release is a difference of large ones.
// Without damping the balance has no integrated part: e (the jumps' loss alone, 1 - e = 9.1e-4)
// is the same at every tolerance, and the integrated rate agrees with it (the closure).
TEST(MaugisViscoelastic, SlowImpactOnALongRangeZone) {
  const Pair pair = ice_pair();
  double first = 0.0;
  for (const char* tolerance : {"1e-6", "1e-8", "1e-12"}) {
    const models::Model m = bounce::testing::model(
        pair, "maugis-viscoelastic", {{"z0", 5e-8}, {"A", 0.0}, {"adhesive_tolerance", std::string(tolerance)}});
    const auto out = collide(pair, m, 0.01);
    ASSERT_EQ(out.outcome, Outcome::bounce);
    if (first == 0.0) first = out.cor;
    EXPECT_EQ(out.cor, first) << tolerance;
    EXPECT_LT(std::abs(fraction(out.energy.closure_error, out)), 1e-6) << tolerance;
  }
  EXPECT_NEAR(first, 1.0 - 9.1e-4, 1e-5);
}

// Sticking: below the sticking velocity the pair sticks and keeps the contact's energies; just
// above it bounces with a small e (the balance reaches 0 at v_s).
TEST(MaugisViscoelastic, SticksBelowTheStickingVelocity) {
  const Pair pair = ice_pair();
  const models::Model m = maugis(pair, 2e-9, 1e-10);
  const double v_s = sticking_velocity(pair, m, {}, 1e-8).velocity;
  const auto below = collide(pair, m, 0.99 * v_s);
  EXPECT_EQ(below.outcome, Outcome::stick);
  EXPECT_EQ(below.cor, 0.0);
  EXPECT_LT(below.energy.surface_remaining, 0.0);
  const auto above = collide(pair, m, 1.01 * v_s);
  EXPECT_EQ(above.outcome, Outcome::bounce);
  EXPECT_LT(above.cor, 0.2);
}

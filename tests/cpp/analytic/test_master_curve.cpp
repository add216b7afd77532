// The viscoelastic master curves against their limits, an independent long-double
// reference (tools/master_reference.hpp) and the library's own integration engine.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/pair/materials_table.hpp"
#include "master_reference.hpp"
#include "model_helpers.hpp"

using namespace bounce;
using namespace bounce::analysis;
using analytic::master_cor;
using analytic::viscoelastic_master;
using models::EndRule;

namespace {
const Pair& ice() {
  static const Pair p = Pair::identical(MaterialTable::builtin().at("ice-bshp96"), 1e-2);
  return p;
}
const Pair& steel_on_wall() {
  static const Pair p(sphere(MaterialTable::builtin().at("steel"), 3e-3), wall(MaterialTable::builtin().at("steel")));
  return p;
}
// The A that gives `kappa` at speed g (kappa is linear in A, BP04 (8.70)): kappa is swept
// through A at a physical speed, as collide() refuses speeds above the sound speed.
double dissipation_for(const Pair& p, double kappa, double g) {
  return kappa / analytic::kappa(1.0, p.hertz_constant(), p.effective_mass(), g);
}
}  // namespace

TEST(MasterCurve, LimitsAndMonotonicity) {
  for (EndRule rule : {EndRule::overlap, EndRule::force}) {
    EXPECT_NEAR(master_cor(0.0, rule), 1.0, 1e-14);
    EXPECT_NEAR(viscoelastic_master(0.0, rule).contact_time, bounce::contact::hertz::scaled_collision_time(), 1e-13);
    EXPECT_NEAR(viscoelastic_master(0.0, rule).max_overlap, 1.0, 1e-14);
    EXPECT_LT(master_cor(1e12, rule), 1e-18);
    double previous = 1.0 + 1e-15;
    for (double log_k = -8.0; log_k <= 12.0; log_k += 0.01) {
      const double e = master_cor(std::pow(10.0, log_k), rule);
      EXPECT_LT(e, previous) << log_k;
      EXPECT_GT(e, 0.0);
      previous = e;
    }
  }
}

// docs/decisions.md D5: the force rule never gives less than the overlap rule; the two agree as
// kappa -> 0, their difference being kappa^{5/2} (32/(75 sqrt 5) + O(kappa)).
TEST(MasterCurve, ForceRuleAboveOverlapRule) {
  for (double log_k = -6.0; log_k <= 9.0; log_k += 0.05) {
    const double k = std::pow(10.0, log_k);
    EXPECT_GE(master_cor(k, EndRule::force), master_cor(k, EndRule::overlap)) << k;
  }
  const double d0 = 32.0 / (75.0 * std::sqrt(5.0));
  for (double k : {1e-4, 1e-3}) {
    const double difference = master_cor(k, EndRule::force) - master_cor(k, EndRule::overlap);
    // relative correction d1 kappa / d0 = -1.5 kappa; 1e-13 absolute accuracy of each curve.
    EXPECT_NEAR(difference / std::pow(k, 2.5), d0, 2.0 * k * d0 + 1e-13 / std::pow(k, 2.5)) << k;
  }
}

// BP04 (8.89): (1 - e)/q -> a1 = 1 and (e - 1 + q)/q^2 -> a2 = 3/5 as g -> 0.
TEST(MasterCurve, ExactLeadingCoefficients) {
  for (EndRule rule : {EndRule::overlap, EndRule::force}) {
    // The force rule adds d0 kappa^{5/2} = 0.187 q^{5/2}: it slows the approach by 0.19 q^{1/2}.
    const double half = rule == EndRule::force ? 0.19 : 0.0;
    for (double k : {1e-3, 3e-3, 1e-2}) {
      const double q = analytic::expansion_variable(k);
      const double e = master_cor(k, rule);
      // Truncation: the next terms are a2 q (0.6 q) and a3 q^3 / q^2 (0.341 q); the tables'
      // absolute round-off near kappa = 0 is below 1e-13, divided by q^2 at most 1e-7.
      EXPECT_NEAR((1.0 - e) / q, 1.0, 0.61 * q + half * q * std::sqrt(q)) << k;
      EXPECT_NEAR((e - 1.0 + q) / (q * q), 0.6, 0.35 * q + half * std::sqrt(q) + 1e-13 / (q * q)) << k;
    }
  }
}

// Independent check: the long-double reference at points that are not Chebyshev nodes
// (random, log-uniform). The stated error is 1e-10; the tables reach ~1e-13.
TEST(MasterCurve, AgreesWithTheLongDoubleReference) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> log_kappa(-6.0, 2.7);
  for (int i = 0; i < 40; ++i) {
    const double k = std::pow(10.0, log_kappa(rng));
    const auto r = reference::master_quantities(k, true);
    const auto o = viscoelastic_master(k, EndRule::overlap);
    const auto f = viscoelastic_master(k, EndRule::force);
    EXPECT_NEAR(o.cor, static_cast<double>(r.cor_overlap), 1e-12) << k;
    EXPECT_NEAR(f.cor, static_cast<double>(r.cor_force), 1e-12) << k;
    EXPECT_NEAR(o.contact_time / static_cast<double>(r.contact_time_overlap), 1.0, 1e-11) << k;
    EXPECT_NEAR(f.contact_time / static_cast<double>(r.contact_time_force), 1.0, 1e-11) << k;
    EXPECT_NEAR(o.max_overlap / static_cast<double>(r.max_overlap), 1.0, 1e-12) << k;
  }
  // The force rule and the maximum overlap out to the asymptotic domain (kappa >= 2^27).
  std::uniform_real_distribution<double> log_large(2.7, 10.0);
  for (int i = 0; i < 15; ++i) {
    const double k = std::pow(10.0, log_large(rng));
    const auto r = reference::master_quantities(k, false);
    const auto f = viscoelastic_master(k, EndRule::force);
    EXPECT_NEAR(f.cor / static_cast<double>(r.cor_force), 1.0, 1e-10) << k;
    EXPECT_NEAR(f.contact_time / static_cast<double>(r.contact_time_force), 1.0, 1e-10) << k;
    EXPECT_NEAR(f.max_overlap / static_cast<double>(r.max_overlap), 1.0, 1e-10) << k;
  }
}

TEST(MasterCurve, ContinuousAcrossItsPieces) {
  for (double edge : {1.0, 2.0, 4.0, 8.0, 16.0, 1024.0, 134217728.0}) {
    for (EndRule rule : {EndRule::overlap, EndRule::force}) {
      const auto below = viscoelastic_master(std::nextafter(edge, 0.0), rule);
      const auto at = viscoelastic_master(edge, rule);
      EXPECT_NEAR(below.cor / at.cor, 1.0, 1e-11) << edge;
      EXPECT_NEAR(below.contact_time / at.contact_time, 1.0, 1e-11) << edge;
      EXPECT_NEAR(below.max_overlap / at.max_overlap, 1.0, 1e-11) << edge;
    }
  }
}

// Acceptance: master curve and direct integration agree to 1e-9 on 1000 random kappa in
// [1e-6, 1e3] (log-uniform), through the public collide() with both methods.
TEST(MasterCurve, AgreesWithDirectIntegration) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> log_kappa(-6.0, 3.0);
  const double g = 1.0;
  CollideOptions integrate;
  integrate.method = Method::integrate;
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double k = std::pow(10.0, log_kappa(rng));
    const auto spec = bounce::testing::viscoelastic(ice(), dissipation_for(ice(), k, g), i % 2 ? "force" : "overlap");
    const double e_master = cor(ice(), spec, g);
    const double e_integrate = cor(ice(), spec, g, integrate);
    worst = std::max(worst, std::abs(e_master - e_integrate));
    EXPECT_NEAR(e_master, e_integrate, 1e-9) << k;
  }
  RecordProperty("worst_difference", std::to_string(worst));
}

// Acceptance: two different pairs with equal kappa give equal e (to 1e-10); both methods.
TEST(MasterCurve, EqualKappaEqualCor) {
  CollideOptions integrate;
  integrate.method = Method::integrate;
  for (double k : {0.01, 0.3, 2.0}) {
    // Different speeds and different A, the same kappa.
    const double g_ice = 2.0, g_steel = 0.3;
    const auto ice_spec = bounce::testing::viscoelastic(ice(), dissipation_for(ice(), k, g_ice));
    const auto steel_spec = bounce::testing::viscoelastic(steel_on_wall(), dissipation_for(steel_on_wall(), k, g_steel));
    EXPECT_NEAR(cor(ice(), ice_spec, g_ice, integrate), cor(steel_on_wall(), steel_spec, g_steel, integrate), 1e-10);
    EXPECT_NEAR(cor(ice(), ice_spec, g_ice), cor(steel_on_wall(), steel_spec, g_steel), 1e-14);
  }
}

// A = 0 gives e = 1 and the exact Hertz contact time, by either method.
TEST(MasterCurve, NoDissipationIsHertz) {
  const auto spec = bounce::testing::viscoelastic(ice(), 0.0);
  const double t_hertz = bounce::contact::hertz::collision_time(ice().hertz_constant(), ice().effective_mass(), 2.0);
  for (Method m : {Method::master, Method::integrate}) {
    CollideOptions o;
    o.method = m;
    const auto out = collide(ice(), spec, 2.0, o);
    EXPECT_NEAR(out.cor, 1.0, 1e-10);
    EXPECT_NEAR(out.contact_time / t_hertz, 1.0, 1e-10);
  }
}

// The overlap-rule tail e = C kappa^-5: C is the exit speed of the universal inner
// problem; the switch at kappa = 8 is seamless because the corrections there are < 1e-15.
TEST(MasterCurve, OverlapTail) {
  EXPECT_NEAR(analytic::overlap_tail_constant(), 10.0749642661479, 1e-11);
  const auto r = reference::master_quantities(7.0L, true);
  EXPECT_NEAR(static_cast<double>(r.cor_overlap) * std::pow(7.0, 5), analytic::overlap_tail_constant(), 1e-9);
  EXPECT_LT(analytic::master_curve_fit_error(), 1e-13);
}

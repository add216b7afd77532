// K13's dynamic model, its limits, jkr-viscoelastic and BP04's adhesive model.
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <boost/math/tools/roots.hpp>
#include <gtest/gtest.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/analytic/adhesive.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/dynamics/adhesive_collision.hpp"
#include "bounce/pair/materials_table.hpp"
#include "model_helpers.hpp"

using namespace bounce;
using namespace bounce::analysis;
using dynamics::Outcome;

namespace {
const Material& ice() { return MaterialTable::builtin().at("water-ice"); }
// K13 §3: the sphere radius for which K13 (22) gives t_H = 1.4e-8 s at 8 m/s.
double k13_sphere_radius() {
  auto t_h = [](double r) {
    const Pair p = Pair::identical(ice(), r);
    return analytic::hertz_contact_time_k13(p.effective_mass(), p.effective_radius(), p.effective_modulus(), 8.0) - 1.4e-8;
  };
  std::uintmax_t iterations = 100;
  const auto r = boost::math::tools::toms748_solve(t_h, 1e-7, 1e-5, boost::math::tools::eps_tolerance<double>(40), iterations);
  return 0.5 * (r.first + r.second);
}
models::Model krijt(const Pair& pair, double tvis, double z0 = 0.2e-9, ParameterInputs more = {}) {
  more.insert({{"tvis", tvis}, {"z0", z0}});
  return bounce::testing::model(pair, "krijt", more);
}
const models::KrijtParameters& krijt_parameters(const models::Model& m) { return m.crack_parameters()[0]; }
double fraction(double part, const dynamics::CollisionOutcome& o) { return part / o.energy.initial_kinetic; }
}  // namespace

// Acceptance: U_K + U_E + U_S + U_CD + U_BD constant to <= 1e-6 of the initial kinetic
// energy over velocities, radii and T_vis, along the trajectory and at the end.
TEST(Krijt, EnergyClosure) {
  for (double r : {2e-7, 2e-6, 2e-4}) {
    const Pair pair = Pair::identical(ice(), r);
    for (double tvis : {1e-15, 1e-12, 1e-10}) {
      for (double v : {0.3, 3.0, 30.0}) {
        CollideOptions o;
        o.record_trajectory = true;
        const auto out = collide(pair, krijt(pair, tvis), v, o);
        EXPECT_LT(std::abs(fraction(out.energy.closure_error, out)), 1e-6) << r << " " << tvis << " " << v;
        for (const auto& s : out.trajectory) {
          const double total = s.kinetic + s.elastic + s.surface + s.crack_dissipated + s.bulk_dissipated;
          ASSERT_NEAR(total / out.energy.initial_kinetic, 1.0, 1e-6) << r << " " << tvis << " " << v << " t=" << s.time;
        }
      }
    }
  }
}

// The crack law is continuous in k (models/crack.hpp, third decision): the issue that asked for
// it measured 0.561780 at k = 0.02 -+ 1e-7 against 0.533235 at k = 0.02 (8 m/s, 1 um ice,
// T_vis = 1e-11 s), when k != 0.02 switched to (16) alone. Now the COR moves with k like
// everything else: dCOR/dk ~ 0.3 here (0.533 at 0.02, 0.558 at 0.1), so +-1e-7 moves it by
// ~3e-8, far below the 1e-4 asked, and the integration's own error (~1e-8) is below that too.
TEST(Krijt, CorIsContinuousInK) {
  const Pair pair = Pair::identical(ice(), 1e-6);
  auto cor = [&](double k) {
    return collide(pair, krijt(pair, 1e-11, 0.2e-9, {{"k", k}}), 8.0).cor;
  };
  const double at = cor(0.02);
  EXPECT_NEAR(at, 0.533235, 2e-6);  // the value K13's own law gives (golden collide-krijt-*)
  EXPECT_NEAR(cor(0.02 - 1e-7), at, 1e-6);
  EXPECT_NEAR(cor(0.02 + 1e-7), at, 1e-6);
}

// The ends of the ranges k and krijt's z0 declare (models/catalogue.cpp; docs/adhesive.md, Validity)
// give an outcome, slow and fast: the issue that narrowed them found k = 1e-12 and z0 = 1e-15 m,
// then declared, failing at 8 m/s.
TEST(Krijt, DeclaredRangesWorkAtBothEnds) {
  const Pair pair = Pair::identical(ice(), 1e-6);
  for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
           {"k", 1e-10}, {"k", 0.5}, {"z0", 1e-12}, {"z0", 1e-6}}) {
    for (double v : {0.1, 8.0, 30.0}) {
      const models::Model m = bounce::testing::model(pair, "krijt", {{"tvis", 1e-11}, {name, value}});
      const auto out = collide(pair, m, v);
      EXPECT_GE(out.cor, 0.0) << name << " " << value << " " << v;
      EXPECT_LE(out.cor, 1.0) << name << " " << value << " " << v;
    }
  }
}

TEST(Krijt, InitialContactOfAppendixB) {
  const Pair pair = Pair::identical(ice(), 2e-6);
  const auto p = krijt_parameters(krijt(pair, 1e-11));
  const auto c = models::krijt_initial_contact(p);
  EXPECT_NEAR(models::effective_surface_energy_ratio(p, c.contact_radius, 0.0), 1.01 * p.k, 1e-12);  // (B.1)
  EXPECT_NEAR(c.crack_dissipated, -models::contact_energy(p, c.contact_radius, 0.0), 1e-30);
  EXPECT_GT(c.time, 0.0);
  EXPECT_LT(c.time, 1e-12);  // the snap-on is practically instantaneous (~1e-14 s for ice)
}

// Acceptance: gamma -> 0 reproduces the viscoelastic model with the same A to 1e-6.
// (The adhesive correction of the force is sqrt(8 pi gamma E* a^3), so the difference
// falls like sqrt(gamma): 3e-7 at 1e-10 J/m^2, 3e-8 at 1e-12.)
TEST(Krijt, ViscoelasticLimit) {
  for (double gamma : {1e-10, 1e-12}) {
    Material m = ice();
    m.surface_energy = gamma;
    const Pair pair = Pair::identical(m, 2e-6);
    const auto k = krijt(pair, 1e-11, 0.2e-9, {{"A", 1.6e-10}});
    const auto v = bounce::testing::viscoelastic(pair, 1.6e-10);
    for (double speed : {1.0, 8.0}) {
      const auto out = collide(pair, k, speed);
      EXPECT_NEAR(out.cor, cor(pair, v, speed), 1e-6) << gamma << " " << speed;
      EXPECT_FALSE(out.notes.empty());  // so stiff that the reduction was used
    }
  }
}

// Acceptance: as T_vis falls from 1e-12 to 1e-16 the COR approaches the elastic JKR
// result monotonically, within 1% of e_JKR (24) for T_vis <= 1e-14 (K13 appendix A:
// e = 0.93 = e_JKR at 1e-14) and v >= 2 v_c.
TEST(Krijt, ElasticJkrLimit) {
  const Pair pair = Pair::identical(ice(), k13_sphere_radius());
  const double v_c = analytic::sticking_velocity_jkr(pair.effective_mass(), pair.effective_radius(),
                                                     pair.effective_modulus(), 0.37);
  for (double factor : {2.0, 4.0, 10.0}) {
    const double v = factor * v_c, e_jkr = analytic::cor_jkr(v, v_c);
    double previous = std::numeric_limits<double>::infinity();
    for (double tvis : {1e-12, 1e-13, 1e-14, 1e-15, 1e-16}) {
      const double deviation = std::abs(cor(pair, krijt(pair, tvis), v) / e_jkr - 1.0);
      EXPECT_LT(deviation, previous) << factor << " " << tvis;
      if (tvis <= 1e-14) {
        EXPECT_LT(deviation, 0.01) << factor << " " << tvis;
      }
      previous = deviation;
    }
  }
}

// Acceptance: krijt approaches jkr-viscoelastic as the crack becomes fast (A fixed, the
// crack speed scale E* z0^2/(gamma T_vis) growing).
TEST(Krijt, FastCrackLimitIsJkrViscoelastic) {
  const Pair pair = Pair::identical(ice(), k13_sphere_radius());
  for (double v : {2.0, 8.0}) {
    const auto jv = bounce::testing::model(pair, "jkr-viscoelastic", {{"A", 1.6e-10}});
    const double target = cor(pair, jv, v);
    double previous = std::numeric_limits<double>::infinity();
    for (double tvis : {1e-12, 1e-13, 1e-14, 1e-15, 1e-16}) {
      const auto k = krijt(pair, tvis, 0.2e-9, {{"A", 1.6e-10}});
      const double difference = std::abs(cor(pair, k, v) - target);
      EXPECT_LT(difference, previous) << v << " " << tvis;
      previous = difference;
    }
    EXPECT_LT(previous, 1e-3);
  }
}

// The singular-perturbation switch is continuous: just above and below the threshold
// the full and the reduced models agree to the integration error.
TEST(Krijt, ReductionIsContinuous) {
  Material m = ice();
  const double v = 8.0;
  for (double gamma : {3e-7, 1e-6, 3e-6}) {
    m.surface_energy = gamma;
    const Pair pair = Pair::identical(m, 2e-6);
    const auto p = krijt_parameters(krijt(pair, 1e-11));
    const auto full = dynamics::integrate_krijt_collision(p, v);
    const auto reduced = dynamics::integrate_jkr_viscoelastic_collision(p, v);
    EXPECT_NEAR(full.cor, reduced.cor, 5e-8) << gamma << " estimate " << models::krijt_hysteresis_estimate(p, v);
  }
}

TEST(JkrViscoelastic, ElasticLimitIsExactJkr) {
  const Pair pair = Pair::identical(ice(), 2e-6);
  const double v_c = analytic::sticking_velocity_jkr(pair.effective_mass(), pair.effective_radius(),
                                                     pair.effective_modulus(), 0.37);
  const auto jv = bounce::testing::model(pair, "jkr-viscoelastic", {{"A", 0.0}});
  for (double f : {1.05, 2.0, 10.0}) EXPECT_NEAR(cor(pair, jv, f * v_c), analytic::cor_jkr(f * v_c, v_c), 1e-8) << f;
  EXPECT_EQ(collide(pair, jv, 0.95 * v_c).outcome, Outcome::stick);
}

// Acceptance: K13 §3 (water ice, T_vis = 1e-11 s, t_H = 1.4e-8 s at 8 m/s). K13 does
// not state z0: with z0 fitted to the one number e_A = 0.66, the others follow:
// sticking at 2 m/s, contact longer than t_H (K13: 1.7e-8 s), crack and bulk losses
// both significant (K13: 37% and 19%), e_A well below e_I = 0.93. docs/adhesive.md.
TEST(Krijt, K13Section3) {
  const Pair pair = Pair::identical(ice(), k13_sphere_radius());
  auto e_at = [&](double z0) { return cor(pair, krijt(pair, 1e-11, z0), 8.0) - 0.66; };
  std::uintmax_t iterations = 60;
  const auto bracket = boost::math::tools::toms748_solve(e_at, 0.06e-9, 0.2e-9, boost::math::tools::eps_tolerance<double>(20), iterations);
  const double z0 = 0.5 * (bracket.first + bracket.second);
  EXPECT_GT(z0, 0.07e-9);
  EXPECT_LT(z0, 0.11e-9);
  const auto fast = collide(pair, krijt(pair, 1e-11, z0), 8.0);
  const auto slow = collide(pair, krijt(pair, 1e-11, z0), 2.0);
  EXPECT_EQ(fast.outcome, Outcome::bounce);
  EXPECT_EQ(slow.outcome, Outcome::stick);
  EXPECT_GT(fast.contact_time, 1.4e-8);
  EXPECT_NEAR(fast.contact_time, 1.7e-8, 0.1e-8);          // K13 prints "~1.7e-8 s"
  EXPECT_NEAR(fraction(fast.energy.crack_dissipated, fast), 0.37, 0.04);
  EXPECT_NEAR(fraction(fast.energy.bulk_dissipated, fast), 0.19, 0.03);
  const auto p = krijt_parameters(krijt(pair, 1e-11, z0));
  const double t_h = analytic::hertz_contact_time_k13(pair.effective_mass(), pair.effective_radius(), pair.effective_modulus(), 8.0);
  const double v_c = analytic::sticking_velocity_k13(pair.effective_mass(), pair.effective_radius(), pair.effective_modulus(), 0.37);
  const double e_i = analytic::cor_independent(analytic::cor_jkr(8.0, v_c), analytic::cor_viscous_k13(p.dissipative_constant, t_h));
  EXPECT_LT(fast.cor, e_i - 0.2);
  // With the default z0 = 0.2 nm the crack is 5x faster (c ~ z0^2): less hysteresis.
  EXPECT_GT(cor(pair, krijt(pair, 1e-11), 8.0), 0.8);
}

// Acceptance: the sticking velocity is continuous and monotone over K13 fig. 5's ranges
// (reduced radius 0.1 um to 100 um, T_vis 1e-14 to 1e-10 s): it falls with the radius
// and grows with T_vis, never below the elastic JKR value. Where it rises steeply (at
// small radii and slow relaxation, towards the sound speed) continuity is checked by
// refinement: a jump must shrink when the radius step is bisected. With slow relaxation
// it diverges at a critical radius (below it the grains stick at every speed: a
// documented error); we follow it while v_s <= 0.1 c_t, the quasi-static validity.
TEST(Krijt, StickingVelocityOverFigure5Ranges) {
  auto v_stick = [](double tvis, double r_eff) {
    const Pair pair = Pair::identical(ice(), 2.0 * r_eff);
    return sticking_velocity(pair, krijt(pair, tvis), {}, 1e-5).velocity;
  };
  std::vector<double> radii;
  for (double r = 1e-4; r >= 0.99e-7; r /= std::pow(10.0, 0.25)) radii.push_back(r);
  const double c_t = std::sqrt(ice().youngs_modulus / (2.0 * ice().density * (1.0 + ice().poisson_ratio)));
  std::vector<double> previous;
  for (double tvis : {1e-14, 1e-12, 1e-11, 1e-10}) {
    std::vector<double> row;
    for (double r_eff : radii) {
      double v_s = 0.0;
      try {
        v_s = v_stick(tvis, r_eff);
      } catch (const NumericalError& e) {
        EXPECT_NE(std::string(e.what()).find("sound speed"), std::string::npos);
        break;  // and for every smaller radius too
      }
      if (v_s > 0.1 * c_t) break;  // outside the quasi-static validity
      const Pair pair = Pair::identical(ice(), 2.0 * r_eff);
      EXPECT_GE(v_s, 0.999 * analytic::sticking_velocity_jkr(pair.effective_mass(), pair.effective_radius(),
                                                             pair.effective_modulus(), 0.37));
      if (!row.empty()) {
        EXPECT_GT(v_s, row.back()) << tvis << " " << r_eff;  // smaller grains stick up to higher speeds
        // JKR scaling gives a factor 10^{0.25 * 5/6} = 1.62 per step; beyond 2.5, refine.
        if (v_s / row.back() > 2.5) {
          double lo = r_eff, hi = r_eff * std::pow(10.0, 0.25), v_lo = v_s, v_hi = row.back();
          for (int level = 0; level < 4; ++level) {
            const double mid = std::sqrt(lo * hi), v_mid = v_stick(tvis, mid);
            EXPECT_LT(v_mid, v_lo);
            EXPECT_GT(v_mid, v_hi);
            (v_lo / v_mid > v_mid / v_hi ? hi : lo) = mid;
            (lo == mid ? v_lo : v_hi) = v_mid;
          }
          EXPECT_LT(v_lo / v_hi, 1.5) << "jump at " << tvis << " " << r_eff;
        }
      }
      row.push_back(v_s);
    }
    EXPECT_GE(row.size(), 5u) << tvis;
    for (std::size_t i = 0; i < std::min(row.size(), previous.size()); ++i) EXPECT_GT(row[i], previous[i]) << tvis;
    previous = row;
  }
}

// BP04 (8.56) alone is conservative: without dissipation (A = B = 0) the grains reach xi = 0
// with their impact speed, and the neck's tensile work W0 (8.95) is the only loss: e is BP04
// (8.98) with e(g) = 1 exactly, to the integration error. Dissipation makes them stick at low
// speed. The xi^{-1/4} cutoff is converged.
TEST(AdhesiveViscoelastic, ConservativeAdhesionAndCutoff) {
  const Pair pair = Pair::identical(ice(), 2e-6);
  const auto conservative = bounce::testing::model(pair, "adhesive-viscoelastic", {{"A", 0.0}, {"B", 0.0}});
  CollideOptions o;
  o.method = Method::integrate;
  const double w0 = analytic::tensile_work(pair.effective_radius(), pair.effective_modulus(), *pair.surface_energy());
  EXPECT_NEAR(cor(pair, conservative, 2.0, o), analytic::cor_adhesive_bp04(1.0, 2.0, w0, pair.effective_mass()), 1e-9);
  const auto s = bounce::testing::model(pair, "adhesive-viscoelastic", {{"A", 1.6e-10}, {"B", 1.6e-10}});
  const auto out = collide(pair, s, 3.0, o);
  EXPECT_EQ(out.outcome, Outcome::bounce);
  EXPECT_LT(std::abs(fraction(out.energy.closure_error, out)), 1e-9);
  EXPECT_EQ(collide(pair, s, 0.3, o).outcome, Outcome::stick);
  const double v_st = sticking_velocity(pair, s).velocity;
  EXPECT_GT(v_st, sticking_velocity_bp04(pair, s));  // (8.100) omits the B term's loss
}

TEST(Krijt, PlasticLossesAdd) {
  const Pair pair = Pair::identical(ice(), 2e-6);
  const double e_a = cor(pair, krijt(pair, 1e-13), 20.0);
  const auto out = collide(pair, krijt(pair, 1e-13, 0.2e-9, {{"yield", 5e7}}), 20.0);
  const double v_y = analytic::yield_velocity(pair.effective_radius(), pair.effective_mass(), pair.effective_modulus(), 5e7);
  ASSERT_LT(v_y, 20.0);
  EXPECT_NEAR(out.cor, analytic::cor_with_plastic(e_a, analytic::cor_thornton_ning(20.0, v_y)), 1e-12);  // (30)
  EXPECT_GT(out.energy.plastic_dissipated, 0.0);
  EXPECT_LT(std::abs(fraction(out.energy.closure_error, out)), 1e-6);
}

// BP04 (8.99): a viscoelastic collision of adhesive grains warns when e g is not well
// above sqrt(2 W0/m) (here 0.876 m/s for 2 um ice spheres), and stays silent far above
// it or without a surface energy.
TEST(AdhesionValidity, Bp04Condition) {
  auto has_warning = [](const Pair& pair, double v) {
    for (const auto& w : collide(pair, bounce::testing::viscoelastic(pair, 1e-10), v).warnings) {
      if (w.find("BP04 (8.99)") != std::string::npos) return true;
    }
    return false;
  };
  const Pair sticky = Pair::identical(ice(), 2e-6);
  EXPECT_TRUE(has_warning(sticky, 1.0));
  EXPECT_FALSE(has_warning(sticky, 10.0));
  const Pair clean = Pair::identical(MaterialTable::builtin().at("ice-bshp96"), 2e-6);
  EXPECT_FALSE(has_warning(clean, 1.0));
}

// A sticking collision stops when sticking is certain: at 0.1 m/s (2 um ice, T_vis =
// 1e-11 s) after 2.6e-17 s, long before the maximum compression. The validity conditions
// (BSHP96 (B12), K13 (A.2)) are about how fast the contact changes, so they compare with
// the elastic Hertz contact time there (3.3e-8 s), not with that stopping time: T_vis =
// 1e-11 s is << 0.1 of it, and 1e-2 nu^2 t_H = 2.1e-11 s > T_vis (nu^2 = T_vis/A = 1/16).
TEST(AdhesionValidity, StickingComparesWithTheHertzTime) {
  const Pair pair = Pair::identical(ice(), 2e-6);
  const auto out = collide(pair, bounce::testing::model(pair, "krijt", {{"tvis", 1e-11}}), 0.1);
  ASSERT_EQ(out.outcome, Outcome::stick);
  const double t_h = bounce::contact::hertz::collision_time(pair.hertz_constant(), pair.effective_mass(), 0.1);
  ASSERT_LT(out.contact_time, 1e-6 * t_h);
  for (const auto& w : out.warnings) {
    EXPECT_EQ(w.find("(B12)"), std::string::npos) << w;
    EXPECT_EQ(w.find("(A.2)"), std::string::npos) << w;
  }
  // A bounce keeps its own contact time (2 um ice, A = 2e-9 s: a contact time near 1e-8 s).
  const auto bounced = collide(pair, bounce::testing::viscoelastic(pair, 2e-9), 5.0);
  ASSERT_EQ(bounced.outcome, Outcome::bounce);
  bool b12 = false;
  for (const auto& w : bounced.warnings) {
    b12 = b12 || (w.find("(B12)") != std::string::npos && w.find("the contact time") != std::string::npos);
  }
  EXPECT_TRUE(b12) << ::testing::PrintToString(bounced.warnings);
}

// --follow T integrates a sticking collision on to time T: the grains settle on the JKR
// equilibrium and stay in contact, so the outcome stays `stick` and the run ends at T with
// the state there (1 um ice at 3 m/s sticks, v_s = 4.2 m/s; jkr-viscoelastic at 0.5 m/s).
// Before, krijt reported a `bounce` with e = |rate at T| / g (3.5e-4 for T = 1e-7 s) and
// jkr-viscoelastic lost the state at T (max_overlap 0, closure error = all the energy).
TEST(Follow, StickingStaysInContactUntilTheEnd) {
  const Pair pair = Pair::identical(ice(), 1e-6);
  for (const char* name : {"krijt", "jkr-viscoelastic"}) {
    SCOPED_TRACE(name);
    const double speed = std::string(name) == "krijt" ? 3.0 : 0.5;
    CollideOptions options;
    options.follow_time = 1e-7;
    const auto out = collide(pair, bounce::testing::model(pair, name, {{"tvis", 1e-11}}), speed, options);
    EXPECT_EQ(out.outcome, Outcome::stick);
    EXPECT_EQ(out.cor, 0.0);
    EXPECT_NEAR(out.contact_time, 1e-7, 1e-7 * 1e-9);  // the event is located to ~1e-12 scaled
    EXPECT_GT(out.max_overlap, 0.0);
    EXPECT_GT(out.steps, 100);
    EXPECT_GT(out.energy.bulk_dissipated, 0.0);
    // The budget closes to the integration tolerance (1e-8 default, tightened): 1e-6 of E0.
    EXPECT_LT(std::abs(fraction(out.energy.closure_error, out)), 1e-6);
    bool noted = false;
    for (const auto& n : out.notes) noted = noted || n.find("followed until") != std::string::npos;
    EXPECT_TRUE(noted);
  }
}

// A followed time shorter than the collision leaves the outcome open there: the run goes
// on until the contact breaks or sticking is certain, so --follow never decides the
// outcome. At 8 m/s (krijt) and 3 m/s (jkr-viscoelastic) the grains bounce, with the e of
// the unfollowed run to the integration tolerance (1e-8 relative; the step sequences
// differ); krijt at 3 m/s followed for 1 ps sticks when sticking is certain, after it.
TEST(Follow, ShortTimesLeaveTheOutcomeToThePhysics) {
  const Pair pair = Pair::identical(ice(), 1e-6);
  CollideOptions follow;
  follow.follow_time = 1e-10;
  for (const auto& [name, speed] : {std::pair{"krijt", 8.0}, std::pair{"jkr-viscoelastic", 3.0}}) {
    SCOPED_TRACE(name);
    const auto m = bounce::testing::model(pair, name, {{"tvis", 1e-11}});
    const auto plain = collide(pair, m, speed);
    const auto followed = collide(pair, m, speed, follow);
    ASSERT_EQ(plain.outcome, Outcome::bounce);
    EXPECT_EQ(followed.outcome, Outcome::bounce);
    EXPECT_NEAR(followed.cor, plain.cor, 1e-7 * plain.cor);
  }
  follow.follow_time = 1e-12;
  const auto stuck = collide(pair, bounce::testing::model(pair, "krijt", {{"tvis", 1e-11}}), 3.0, follow);
  EXPECT_EQ(stuck.outcome, Outcome::stick);
  EXPECT_GT(stuck.contact_time, 1e-12);
  ASSERT_FALSE(stuck.notes.empty());
  EXPECT_NE(stuck.notes.back().find("still open"), std::string::npos) << stuck.notes.back();
}

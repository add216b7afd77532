// krijt as a DEM contact law (models::DemCrackLaw, LAMMPS's pair_style bounce): its
// contact forms as K13 appendix B has it, its radius moves by a crack step stable for any dt and
// of second order along uniform steps, its energy released closes the contact's energy budget,
// and no neck holds beyond its release overlap.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "bounce/api/front_door.hpp"
#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/models/krijt.hpp"

using namespace bounce;

namespace {

constexpr double pi = std::numbers::pi;

// Two 1 um water-ice grains (K13 table 2), as LAMMPS gives them to the law.
struct Ice {
  explicit Ice(double tvis, double z0 = 2e-10)
      : law(api::dem_model({{"model", std::string("krijt")},
                              {"material", std::string("water-ice")},
                              {"tvis", tvis},
                              {"z0", z0}})) {}
  models::DemModel law;
  const models::DemCrackLaw& crack() const { return *law.crack; }
  models::ContactGeometry g{0.5e-6, 0.5 * 1000.0 * 4.0 / 3.0 * pi * 1e-18};
  double modulus = 7e9 / (2.0 * (1.0 - 0.25 * 0.25));  // E* of like bodies
  double gamma = 0.37;
  double beta(double a, double delta) const {  // K13 (14)
    const double w = a * a - delta * g.effective_radius;
    return modulus * w * w / (2.0 * pi * a * g.effective_radius * g.effective_radius * gamma);
  }
  double energy(double delta, const models::CrackState& s) const {
    return crack().elastic_energy(g, delta, s) + crack().surface_energy(g, s);
  }
};

}  // namespace

// K13 appendix B: the contact forms at overlap 0 with beta = 1.01 k, releasing -(U_E + U_S).
TEST(KrijtContact, FormsAsAppendixB) {
  const Ice ice(1e-11);
  double released = 0.0;
  const models::CrackState s = ice.crack().form(ice.g, released);
  EXPECT_NEAR(ice.beta(s.contact_radius, 0.0), 1.01 * 0.02, 1e-12);
  EXPECT_GT(released, 0.0);
  EXPECT_NEAR(released, -ice.energy(0.0, s), 1e-12 * released);
}

// Beyond the release overlap beta > (1 - 1e-6)/k for every radius (the closed form at its least,
// a^2 = d/3, checked on a fine grid), and a step there breaks the contact from any radius.
TEST(KrijtContact, NoNeckHoldsBeyondTheReleaseOverlap) {
  const Ice ice(1e-11);
  const double release = ice.crack().release_overlap(ice.g);
  ASSERT_LT(release, 0.0);
  const double top = (1.0 - models::krijt_break_margin) / 0.02;
  double least = INFINITY;
  const double a_least = std::sqrt(-release * ice.g.effective_radius / 3.0);
  for (double x = 0.5; x < 2.0; x += 1e-5) least = std::min(least, ice.beta(x * a_least, release));
  EXPECT_NEAR(least, top, 1e-8 * top);  // the grid's step 1e-5 gives 1e-10 at a minimum
  for (double a : {1e-9, 3e-8, 1e-7, 3e-7}) {
    models::CrackState s{a, 0.0, 0.0};
    EXPECT_TRUE(ice.crack().advance(ice.g, release, 1.001 * release, 1e-12, s).broken) << a;
  }
}

// Stable for any crack speed and step: from T_vis = 1e-20 s (c dt up to 1e15 a) to 1e-6 s, along
// loading and unloading, the radius stays finite and positive (or the contact breaks), the energy
// each step releases is finite, and in all it is positive (a step's own can be slightly negative:
// it is averaged over the step's two overlaps).
TEST(KrijtContact, StepIsStableForAnyCrackSpeed) {
  for (double tvis : {1e-20, 1e-14, 1e-11, 1e-8, 1e-6}) {
    for (double dt : {1e-13, 1e-10, 1e-7}) {
      SCOPED_TRACE(std::to_string(tvis) + " " + std::to_string(dt));
      const Ice ice(tvis);
      double released = 0.0;
      models::CrackState s = ice.crack().form(ice.g, released);
      double delta = 0.0;
      for (int n = 1; n <= 400; n++) {
        const double next = 2e-8 * std::sin(pi * n / 200.0);  // in to 20 nm and out to -20 nm
        const models::CrackAdvance a = ice.crack().advance(ice.g, delta, next, dt, s);
        ASSERT_TRUE(std::isfinite(a.dissipated));
        released += a.dissipated;
        delta = next;
        if (a.broken) break;
        ASSERT_TRUE(std::isfinite(s.contact_radius) && s.contact_radius > 0.0);
      }
      EXPECT_GT(released, 0.0);
    }
  }
}

// The fast-crack limit: with T_vis = 1e-20 s the radius is on the JKR branch, and pulling the
// grains apart in steps of 0.01 nm breaks the contact at the JKR fold delta_c.
TEST(KrijtContact, FastCrackIsJkr) {
  const Ice ice(1e-20);
  const contact::jkr::Parameters jkr{ice.g.effective_radius, ice.modulus, ice.gamma};
  const contact::jkr::DisplacementBranch branch(jkr);
  double released = 0.0;
  models::CrackState s = ice.crack().form(ice.g, released);
  double delta = 0.0;
  for (double next : {1e-9, 3e-9, 1e-9, 0.0}) {
    ice.crack().advance(ice.g, delta, next, 1e-10, s);
    delta = next;
    EXPECT_NEAR(s.contact_radius, branch.radius(delta), 1e-6 * branch.radius(delta)) << delta;
  }
  const double fold = contact::jkr::separation_overlap(jkr);
  while (!ice.crack().advance(ice.g, delta, delta - 1e-11, 1e-10, s).broken) delta -= 1e-11;
  EXPECT_NEAR(delta, fold, 2e-11) << "broke at " << delta << ", the fold is at " << fold;
}

// Second order along uniform steps (BDF2): a(T) after a loading path integrated in 25, 50 and
// 100 steps against 3200; the error falls by 3 or more per halving (order >= 1.6; measured ~2).
TEST(KrijtContact, RadiusIsOfSecondOrderAlongUniformSteps) {
  const Ice ice(1e-11);
  const double total = 2e-9;
  auto run = [&](int steps) {
    double released = 0.0;
    models::CrackState s = ice.crack().form(ice.g, released);
    // Start a little way in, so that the singular start (appendix B) is not what is measured.
    ice.crack().advance(ice.g, 0.0, 1e-10, 1e-11, s);
    s.previous_step = 0.0;
    for (int n = 0; n < steps; n++) {
      const double from = 1e-10 + 1e-8 * std::sin(pi * n / (2.0 * steps));
      const double to = 1e-10 + 1e-8 * std::sin(pi * (n + 1) / (2.0 * steps));
      ice.crack().advance(ice.g, from, to, total / steps, s);
    }
    return s.contact_radius;
  };
  const double reference = run(3200);
  const double e25 = std::abs(run(25) - reference), e50 = std::abs(run(50) - reference),
               e100 = std::abs(run(100) - reference);
  EXPECT_GE(e25 / e50, 3.0) << e25 << " " << e50 << " " << e100;
  EXPECT_GE(e50 / e100, 3.0) << e25 << " " << e50 << " " << e100;
}

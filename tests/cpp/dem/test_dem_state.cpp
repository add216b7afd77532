// The DEM contact's typed state (dem/state.hpp) and its step checks (dem/step_check.hpp): a state
// written to its flat array mid-contact and read back continues bit for bit; seen from the other
// body a contact gives the equal and opposite force and torque; a layout holds what its laws use;
// the step check's stiffness and damping are Hertz's and the viscoelastic law's.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bounce/api/front_door.hpp"
#include "dem/two_spheres.hpp"

using namespace bounce;
using test::Sphere;
using TwoSpheres = test::TwoSpheres<>;

namespace {

// Two 1 um ice grains with krijt and friction, oblique and spinning: every sub-model's state moves.
models::DemModel krijt_with_friction() {
  return api::dem_model({{"material", std::string("water-ice")}, {"model", std::string("krijt")}, {"tvis", 1e-12},
                           {"friction", 0.3}, {"asperity", 1e-9}});
}

std::pair<Sphere, Sphere> oblique() {
  Sphere a, b;
  a.radius = b.radius = 1e-6;
  a.mass = b.mass = 4.0 / 3.0 * M_PI * 1e-18 * 917.0;
  a.x[0] = -1e-6, b.x[0] = 1e-6;
  a.v[0] = 1.5, b.v[0] = -1.5, a.v[1] = 0.5, b.v[1] = -0.5;
  a.omega[2] = 2e5;
  return {a, b};
}

constexpr double time_step = 5e-11;  // about t_H/100 for these grains at 3 m/s

}  // namespace

// The run whose state goes through its flat array at step 150 (in contact) ends where the run that
// kept it does, to the last bit: the flat array holds every field the step reads.
TEST(DemState, FlatArrayMidContactContinuesBitForBit) {
  const models::DemModel law = krijt_with_friction();
  auto [a, b] = oblique();
  TwoSpheres kept(law, a, b, time_step), flat(law, a, b, time_step);
  kept.setup(), flat.setup();
  kept.run(800);
  flat.run(150);
  ASSERT_TRUE(flat.state().touching);
  ASSERT_NE(flat.state().get<dem::Tangential::State>().spring[1], 0.0);
  std::vector<double> history(flat.layout().size());
  flat.layout().write(flat.state(), history.data());
  flat.state() = flat.layout().read(true, history.data());
  flat.run(650);
  for (int k = 0; k < 2; k++)
    for (int d = 0; d < 3; d++) {
      EXPECT_EQ(kept.sphere(k).v[d], flat.sphere(k).v[d]);
      EXPECT_EQ(kept.sphere(k).omega[d], flat.sphere(k).omega[d]);
    }
}

// Body 2's view (j, i) with the reversed flat array gives -F on it and body 1's torque as its
// body 2's, exactly: n, the sliding and the spring all change sign, and negation is exact.
TEST(DemState, OtherBodyViewGivesEqualAndOppositeLoads) {
  const models::DemModel law = krijt_with_friction();
  auto [a, b] = oblique();
  TwoSpheres run(law, a, b, time_step);
  run.setup();
  run.run(150);
  const dem::Layout& layout = run.layout();
  std::vector<double> mine(layout.size()), theirs(layout.size());
  layout.write(run.state(), mine.data());
  layout.reverse(mine.data(), theirs.data());
  dem::ContactState ij = layout.read(true, mine.data()), ji = layout.read(true, theirs.data());
  const Sphere &one = run.sphere(0), &two = run.sphere(1);
  const double r = std::hypot(one.x[0] - two.x[0], one.x[1] - two.x[1], one.x[2] - two.x[2]);
  const dem::Kinematics kij = dem::pair_kinematics(one.motion(), two.motion(), r);
  const dem::Kinematics kji = dem::pair_kinematics(two.motion(), one.motion(), r);
  const dem::StepSettings s{time_step, true, true};
  const dem::Loads lij = dem::loads(dem::step(law, run.geometry(), kij, s, ij), kij, one.radius, two.radius);
  const dem::Loads lji = dem::loads(dem::step(law, run.geometry(), kji, s, ji), kji, two.radius, one.radius);
  ASSERT_NE(lij.torque1[2], 0.0);
  for (int d = 0; d < 3; d++) {
    EXPECT_EQ(lij.force[d], -lji.force[d]);
    EXPECT_EQ(lij.torque1[d], lji.torque2[d]);
    EXPECT_EQ(lij.torque2[d], lji.torque1[d]);
  }
  // And the states they leave are each other's reverse.
  std::vector<double> after_ij(layout.size()), after_ji(layout.size()), back(layout.size());
  layout.write(ij, after_ij.data());
  layout.write(ji, after_ji.data());
  layout.reverse(after_ji.data(), back.data());
  EXPECT_EQ(after_ij, back);
}

// A layout holds the states its laws use, in SubStates' order: the spring and the normal state
// for every law (5 values, as restart files have had them), krijt's crack besides (13), and the
// rolling, sliding and twisting pointers (7) where a law has them (20 at most).
TEST(DemState, LayoutHoldsWhatItsLawsUse) {
  dem::Layout plain;
  plain.add(api::dem_model({{"model", std::string("hertz")}, {"E", 1e9}, {"nu", 0.3}}));
  EXPECT_EQ(plain.size(), 5);
  dem::Layout both = plain;
  both.add(krijt_with_friction());
  EXPECT_EQ(both.size(), 13);
  EXPECT_EQ(dem::Layout::largest, 20);
  dem::ContactState s;
  s.get<dem::Tangential::State>().spring = {1, 2, 3};
  s.get<dem::NormalState>() = {4, 5};
  s.get<dem::CrackStepState>() = {{6, 7, 8, 9}, 10, 11, 12, 13};
  std::vector<double> flat(13);
  both.write(s, flat.data());
  EXPECT_EQ(flat, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13}));
  std::vector<double> short_flat(5);
  plain.write(s, short_flat.data());
  EXPECT_EQ(short_flat, (std::vector<double>{1, 2, 3, 4, 5}));
  EXPECT_EQ(plain.read(true, short_flat.data()).get<dem::CrackStepState>().crack.contact_radius, 0.0);
  models::DemModel rolling = krijt_with_friction();
  rolling.resistance = models::ResistanceModel{{}, 8e-10, true, false, false};
  dem::Layout all;
  all.add(rolling);
  EXPECT_EQ(all.size(), 20);
  s.get<dem::Resistance::State>() = {{14, 15, 16}, {17, 18, 19}, 20};
  std::vector<double> whole(20);
  all.write(s, whole.data());
  EXPECT_EQ(whole, (std::vector<double>{1, 2, 3, 14, 15, 16, 17, 18, 19, 20, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13}));
  const dem::ContactState back = all.read(true, whole.data());
  EXPECT_EQ(back.get<dem::Resistance::State>().pointer2[2], 19.0);
  EXPECT_EQ(back.get<dem::Resistance::State>().twist, 20.0);
}

// Hertz's stiffness dF/dxi = 2 E* sqrt(R xi) (from F = (4/3) E* sqrt(R) xi^{3/2}) and the
// viscoelastic law's damping D = 2 E* A sqrt(R xi) (BSHP96 (2)), by the check's difference
// quotients to their probe's 1e-6 (a forward difference of xi^{3/2}: (3/8) 1e-6 relative).
TEST(DemStepCheck, StiffnessAndDampingAreTheLaws) {
  const double E = 1e9, nu = 0.3, A = 1e-6, R = 5e-4, m = 1e-6, xi = 1e-6, rate = 0.2, dt = 1e-7;
  const double e_star = E / (2 * (1 - nu * nu));
  const models::DemModel law = api::dem_model({{"model", std::string("viscoelastic")}, {"E", E}, {"nu", nu}, {"A", A}});
  const dem::StepCheck c = dem::check_step(*law.normal, {R, m}, xi, rate, dt, 1.0);
  EXPECT_NEAR(c.stiffness / (2 * e_star * std::sqrt(R * xi)), 1.0, 1e-6);
  EXPECT_NEAR(c.damping / (2 * e_star * A * std::sqrt(R * xi)), 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(c.stability, 0.25 * c.stiffness * dt * dt / m + c.damping * dt / m);
  // largest_step is where the stability is 1: rebuilt at that dt, within round-off.
  const double longest = c.largest_step(dt);
  const dem::StepCheck at = dem::check_step(*law.normal, {R, m}, xi, rate, longest, 1.0);
  EXPECT_NEAR(at.stability, 1.0, 1e-9);
}

// A contact is checked where its overlap first exceeds 1.2 times its last checked one.
TEST(DemStepCheck, RecheckedAtAFifthMoreOverlap) {
  double checked = 0.0;
  EXPECT_FALSE(dem::check_due(0.0, checked));
  EXPECT_TRUE(dem::check_due(1e-9, checked));
  EXPECT_EQ(checked, 1e-9);
  EXPECT_FALSE(dem::check_due(1.2e-9, checked));
  EXPECT_TRUE(dem::check_due(1.21e-9, checked));
  EXPECT_EQ(checked, 1.21e-9);
}

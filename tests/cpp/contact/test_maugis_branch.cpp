// The whole Maugis-Dugdale curve of a collision (contact/maugis_branch.hpp): its contact part is
// maugis.hpp's, its zone-alone part joins it, its energy is the force's work, and its limits are
// JKR's and DMT's.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "bounce/contact/maugis.hpp"
#include "bounce/contact/maugis_branch.hpp"

using namespace bounce::contact;

namespace {
const std::vector<double> lambdas = {1e-3, 0.05, 0.3, 1.0, 3.0, 10.0, 100.0, 1e3};
}

// In contact the curve is (MD1)-(MD3) at its own A: maugis.hpp solves (MD1) for s at that A;
// both to (MD1)'s solve, ~1e-13 of the values.
TEST(MaugisBranch, ContactPartIsMaugisDugdale) {
  for (double lambda : lambdas) {
    const maugis::Branch b(lambda);
    for (double tau = 1.02; tau < 1.995; tau += 0.0371) {
      const maugis::BranchPoint p = b.at(b.place(tau));
      const maugis::Point q = maugis::at_contact_radius(lambda, p.contact_radius);
      EXPECT_NEAR(p.force, q.force, 1e-11 * (1.0 + std::abs(q.force))) << lambda << " " << tau;
      EXPECT_NEAR(p.overlap, q.overlap, 1e-11 * (1.0 + std::abs(q.overlap))) << lambda << " " << tau;
    }
  }
}

// Before contact the zone alone ends where (MD1) at A = 0 begins: the two parts meet.
TEST(MaugisBranch, PartsMeetAtTheCentresTouching) {
  for (double lambda : lambdas) {
    const maugis::Branch b(lambda);
    const maugis::BranchPoint before = b.at(b.place(1.0)), after = b.at(b.place(1.0 + 1e-9));
    EXPECT_NEAR(before.force, after.force, 1e-6 * std::abs(before.force)) << lambda;
    EXPECT_NEAR(before.overlap, after.overlap, 1e-6 * std::abs(before.overlap)) << lambda;
    const maugis::Point zero = maugis::at_contact_radius(lambda, 0.0);
    // (maugis.cpp writes C0's quadratic with its own coefficients: 5e-12 apart at lambda = 1e-3.)
    EXPECT_NEAR(before.force, zero.force, 1e-11 * std::abs(zero.force)) << lambda;
    EXPECT_NEAR(before.overlap, zero.overlap, 1e-11 * std::abs(zero.overlap)) << lambda;
    EXPECT_DOUBLE_EQ(b.at(b.place(0.0)).overlap, b.snap_overlap());
    EXPECT_EQ(b.at(b.place(0.0)).force, 0.0);
  }
}

// Delta has one minimum along the curve (the fold): it falls before, rises after. The stable
// states are those after it; the fold agrees with maugis.hpp's least overlap where it is in
// contact, and the pull-off with its least force.
TEST(MaugisBranch, OneFoldAndThePullOff) {
  for (double lambda : lambdas) {
    const maugis::Branch b(lambda);
    const double fold = b.order(b.fold_place());
    double last = b.at(b.place(0.0)).overlap;
    for (double tau = 1e-4; tau < 2.0; tau += 1e-4) {
      const double d = b.at(b.place(tau)).overlap;
      if (tau < fold - 1e-4) {
        EXPECT_LT(d, last) << lambda << " " << tau;
      } else if (tau > fold + 1e-4) {
        EXPECT_GT(d, last) << lambda << " " << tau;
      }
      last = d;
    }
    const maugis::Curve curve(lambda);
    if (b.fold_place().contact) {
      EXPECT_NEAR(b.fold().overlap, curve.min_overlap().overlap, 1e-9) << lambda;
    }
    EXPECT_NEAR(b.pull_off().force, curve.pull_off().force, 1e-9 * std::abs(curve.pull_off().force)) << lambda;
  }
}

// The stable state at an overlap is found again from its overlap, and the energy's slope is the
// force (central differences of relative step 1e-6: truncation ~1e-12, the quadrature ~1e-13).
TEST(MaugisBranch, EnergyIsTheForcesWork) {
  for (double lambda : lambdas) {
    const maugis::Branch b(lambda);
    const double fold = b.order(b.fold_place());
    for (double f : {0.01, 0.5, 0.99}) {
      const double tau = fold + f * (2.0 - fold);
      const maugis::BranchPoint p = b.at(b.place(tau));
      EXPECT_NEAR(b.order(b.place_at_overlap(p.overlap)), tau, 1e-9) << lambda << " " << tau;
      const double h = 1e-6 * (1.0 + std::abs(p.overlap));
      const double slope = (b.energy_at_overlap(p.overlap + h) - b.energy_at_overlap(p.overlap - h)) / (2.0 * h);
      EXPECT_NEAR(slope, p.force, 1e-6 * (1.0 + std::abs(p.force))) << lambda << " " << tau;
    }
  }
}

// The JKR limit (lambda -> inf): the zone shrinks into the contact's edge, the adhesive energy is
// the contact area's, -A^2 (-pi w a^2), the snap is at Delta = 0 and the fold is JKR's:
// A_c = (1/6)^{1/3} (maugis.hpp's units), Delta_c = A_c^2 - sqrt(8 A_c/3). At lambda = 1e3 the
// curve differs from JKR's by ~1/lambda^2 in the force and ~1/lambda in the zone's width.
TEST(MaugisBranch, JkrLimit) {
  const double lambda = 1e3;
  const maugis::Branch b(lambda), down(lambda * (1.0 - maugis::Branch::lambda_step)),
      up(lambda * (1.0 + maugis::Branch::lambda_step));
  EXPECT_NEAR(b.snap_overlap(), 0.0, 1e-3);
  const double a_c = std::cbrt(1.0 / 6.0);
  EXPECT_NEAR(b.fold().overlap, a_c * a_c - std::sqrt(8.0 * a_c / 3.0), 1e-5);
  for (double overlap : {-0.5, 0.0, 1.0, 3.0}) {
    const maugis::BranchPoint p = b.at_overlap(overlap);
    const double a = p.contact_radius;
    EXPECT_NEAR(b.surface_energy_at_overlap(overlap, down, up), -a * a, 3e-3 * (1.0 + a * a)) << overlap;
  }
}

// The DMT limit (lambda -> 0): the pull-off force tends to -2 (-2 pi w R), and the curve is stable
// from the zone's first growth on: the snap and the fold come together, no hysteresis.
TEST(MaugisBranch, DmtLimit) {
  for (double lambda : {1e-2, 1e-3}) {
    const maugis::Branch b(lambda);
    EXPECT_NEAR(b.pull_off().force, -2.0, 3.0 * std::pow(lambda, 1.5) + 1e-3 * lambda) << lambda;
    EXPECT_FALSE(b.fold_place().contact) << lambda;
    // The energy the snap and the jump-off dissipate between them: U(fold) - U(snapped state).
    const double loop = b.energy(b.fold_place()) - b.energy_at_overlap(b.snap_overlap());
    EXPECT_GT(loop, 0.0) << lambda;
    EXPECT_LT(loop, 1e-3 * std::abs(b.energy_at_overlap(0.0))) << lambda;
  }
}

// The energy's table against the force's work along the stable part by Simpson's rule over the
// overlap (2000 intervals in contact, where the force is smooth: error ~1e-13 of it; the force's
// slope jumps where the centre touches, which would cost Simpson 1e-9).
TEST(MaugisBranch, EnergyTableIsExact) {
  for (double lambda : lambdas) {
    const maugis::Branch b(lambda);
    const double lo = std::max(b.fold().overlap + 0.2 * (1.0 + std::abs(b.fold().overlap)), b.at(b.place(1.0)).overlap + 0.1);
    const double hi = lo + 2.0;
    const int n = 2000;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      sum += w * b.at_overlap(lo + (hi - lo) * i / n).force;
    }
    const double simpson = sum * (hi - lo) / (3.0 * n);
    const double table = b.energy_at_overlap(hi) - b.energy_at_overlap(lo);
    EXPECT_NEAR(table, simpson, 1e-11 * (1.0 + std::abs(simpson))) << lambda << " " << lo;
  }
}

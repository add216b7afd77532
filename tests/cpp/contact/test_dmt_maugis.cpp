// DMT, and Maugis-Dugdale reaching JKR and DMT in its limits.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "bounce/contact/dmt.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/contact/maugis.hpp"
#include "bounce/pair/materials_table.hpp"

using namespace bounce;

namespace {
constexpr double pi = std::numbers::pi;
// Non-dimensional JKR (Johnson & Greenwood): P = A^3 - sqrt(6) A^{3/2}, Delta = A^2 - sqrt(8A/3).
double jkr_force(double A) { return A * A * A - std::sqrt(6.0) * std::pow(A, 1.5); }
double jkr_overlap(double A) { return A * A - std::sqrt(8.0 * A / 3.0); }
}  // namespace

TEST(Dmt, PullOffIsMinusTwoPiGammaR) {
  const contact::dmt::Parameters p{0.75e-6, 5e9, 0.2};
  EXPECT_DOUBLE_EQ(contact::dmt::pull_off_force(p), -2.0 * pi * 0.2 * 0.75e-6);
  EXPECT_DOUBLE_EQ(contact::dmt::force(p, 0.0), contact::dmt::pull_off_force(p));
  EXPECT_GT(contact::dmt::force(p, 1e-12), contact::dmt::pull_off_force(p));
  const double f = 3e-7;
  EXPECT_NEAR(contact::dmt::force(p, contact::dmt::overlap_from_force(p, f)) / f, 1.0, 1e-13);
}

// The JKR limit: the measured error of the pull-off force and of the zero-load radius
// falls as lambda^-2 (coefficients 0.164 and 0.46); we test bounds 0.2/lambda^2 and
// 0.5/lambda^2 and that the whole curve converges.
TEST(Maugis, JkrLimit) {
  for (double lambda : {1e2, 1e3}) {
    const double bound = 1.0 / (lambda * lambda);
    const auto pull = contact::maugis::pull_off(lambda);
    EXPECT_NEAR(pull.force, -1.5, 0.2 * bound) << lambda;
    EXPECT_NEAR(pull.contact_radius, std::cbrt(1.5), 1e-4) << lambda;  // flat minimum
    EXPECT_NEAR(contact::maugis::at_force(lambda, 0.0).contact_radius, std::cbrt(6.0), 0.5 * bound);
    EXPECT_NEAR(contact::maugis::min_overlap(lambda).overlap, jkr_overlap(std::cbrt(1.0 / 6.0)), 0.5 * bound);
    for (double A : {0.3, 1.0, 2.0}) {
      const auto point = contact::maugis::at_contact_radius(lambda, A);
      EXPECT_NEAR(point.force, jkr_force(A), 5.0 * bound) << A;
      EXPECT_NEAR(point.overlap, jkr_overlap(A), 5.0 * bound) << A;
    }
  }
}

// The DMT limit: P = A^3 - 2, Delta = A^2. Measured: the pull-off error falls as
// lambda^1.5 (coefficient 1.7), the zero-load radius as lambda (coefficient 1.0);
// we test 2 lambda^1.5 and 2 lambda. The overlap converges only as sqrt(lambda): for
// lambda -> 0, (MD1) gives s ~ 2/(A sqrt(pi lambda)), so (MD3) has the leading
// correction Delta = A^2 - (8/3) sqrt(lambda/pi); we test that term to O(lambda).
TEST(Maugis, DmtLimit) {
  for (double lambda : {1e-3, 1e-4}) {
    EXPECT_NEAR(contact::maugis::pull_off(lambda).force, -2.0, 2.0 * std::pow(lambda, 1.5)) << lambda;
    EXPECT_NEAR(contact::maugis::at_force(lambda, 0.0).contact_radius, std::cbrt(2.0), 2.0 * lambda);
    const auto point = contact::maugis::at_contact_radius(lambda, 1.5);
    EXPECT_NEAR(point.force, 1.5 * 1.5 * 1.5 - 2.0, 20.0 * lambda);
    EXPECT_NEAR(point.overlap, 2.25 - 8.0 / 3.0 * std::sqrt(lambda / pi), 2.0 * lambda);
  }
}

TEST(Maugis, PullOffLiesBetweenJkrAndDmt) {
  double previous = -2.0;
  for (double lambda : {0.01, 0.1, 0.3, 1.0, 3.0, 10.0}) {
    const double p = contact::maugis::pull_off(lambda).force;
    EXPECT_GT(p, previous) << lambda;  // monotone from DMT (-2) to JKR (-1.5)
    EXPECT_LT(p, -1.5);
    previous = p;
  }
}

TEST(Maugis, ZeroRadiusLimitIsContinuous) {
  for (double lambda : {0.1, 1.0, 5.0}) {
    const auto at0 = contact::maugis::at_contact_radius(lambda, 0.0);
    const auto near0 = contact::maugis::at_contact_radius(lambda, 1e-7);
    EXPECT_NEAR(near0.force, at0.force, 1e-5) << lambda;
    EXPECT_NEAR(near0.overlap, at0.overlap, 1e-5) << lambda;
  }
}

TEST(Maugis, LawInSiUnitsMatchesJkrForLargeTabor) {
  // 1 mm ice spheres: mu ~ 85, lambda ~ 100: the SI law must sit within 1e-4 of JKR.
  const Pair pair = Pair::identical(MaterialTable::builtin().at("water-ice"), 1e-3);
  const auto md = contact::make_contact_law("maugis", pair);
  const auto jk = contact::make_contact_law("jkr", pair);
  EXPECT_NEAR(md->adhesion()->pull_off_force / jk->adhesion()->pull_off_force, 1.0, 1e-4);
  EXPECT_NEAR(md->at_force(0.0).contact_radius / jk->at_force(0.0).contact_radius, 1.0, 1e-4);
  const double f = 5.0 * std::abs(jk->adhesion()->pull_off_force);
  EXPECT_NEAR(md->at_force(f).overlap / jk->at_force(f).overlap, 1.0, 1e-4);
}

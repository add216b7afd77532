// The K13 crack law (16)/(17), its C1 join, and the law carried to any k (models/crack.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "bounce/models/crack.hpp"
#include "bounce/models/krijt.hpp"

using namespace bounce::models;

TEST(CrackLaw, SignsAndLimits) {
  for (double k : {0.02, 0.1}) {
    EXPECT_GT(crack_speed_function(1.001 * k, k).value, 100.0);         // closing crack races near beta = k
    EXPECT_LT(crack_speed_function(0.999 / k, k).value, -100.0);        // opening crack races near 1/k
    EXPECT_EQ(crack_speed_function(1.0, k).value, 0.0);                 // JKR equilibrium
    for (double beta = 1.05 * k; beta < 0.95 / k; beta *= 1.1) {
      const double f = crack_speed_function(beta, k).value;
      EXPECT_TRUE(beta < 1.0 ? f > 0.0 : f < 0.0) << beta;              // a' has the sign of 1 - beta
    }
  }
}

TEST(CrackLaw, PrintedFormulas) {
  // (16) at beta = 0.5, k = 0.02: 0.15 / (0.5 ln(0.98/0.5)); (17) at beta = 0.5: x = 1.
  EXPECT_NEAR(crack_speed_high(0.5, 0.02).value, 0.15 / (0.5 * std::log(0.98 / 0.5)), 1e-15);
  EXPECT_NEAR(crack_speed_low(0.5).value, 0.1035 + 0.3421, 1e-15);
  EXPECT_NEAR(crack_speed_low(2.0).value, -(0.2112 + 0.3939), 1e-15);
  EXPECT_NEAR(crack_speed_high(2.0, 0.02).value, -0.48 / std::log(0.98 / 0.5), 1e-15);
  // k = 0.02 uses (17) inside [0.31, 3.6] and (16) outside [0.29, 3.7].
  EXPECT_EQ(crack_speed_function(0.5, 0.02).value, crack_speed_low(0.5).value);
  EXPECT_EQ(crack_speed_function(0.2, 0.02).value, crack_speed_high(0.2, 0.02).value);
  EXPECT_EQ(crack_speed_function(5.0, 0.02).value, crack_speed_high(5.0, 0.02).value);
  // The two fits differ by 0.7% and 0.5% where (17) stops being valid: why we blend.
  EXPECT_NEAR(crack_speed_low(0.29).value / crack_speed_high(0.29, 0.02).value, 1.007, 0.002);
  EXPECT_NEAR(crack_speed_low(3.7).value / crack_speed_high(3.7, 0.02).value, 0.995, 0.002);
}

// The derivative is exact (central differences, h = 1e-6 beta: truncation ~1e-12
// relative), and the blended law is continuous with a continuous derivative.
TEST(CrackLaw, DerivativeAndContinuity) {
  for (double k : {0.02, 0.1}) {
    for (double beta : {0.03, 0.2, 0.295, 0.3, 0.305, 0.6, 0.95, 1.05, 2.0, 3.65, 3.69, 5.0, 9.0}) {
      if (beta <= k || beta >= 1.0 / k) continue;
      const double h = 1e-6 * beta;
      const double fd = (crack_speed_function(beta + h, k).value - crack_speed_function(beta - h, k).value) / (2 * h);
      const double d = crack_speed_function(beta, k).derivative;
      EXPECT_NEAR(fd, d, 1e-6 * std::abs(d) + 1e-9) << k << " " << beta;
    }
  }
  for (double edge : {0.29, 0.31, 3.6, 3.7}) {
    const double eps = 1e-9;
    const auto below = crack_speed_function(edge - eps, 0.02), above = crack_speed_function(edge + eps, 0.02);
    EXPECT_NEAR(below.value, above.value, 1e-7) << edge;
    EXPECT_NEAR(below.derivative, above.derivative, 1e-5 * std::abs(above.derivative)) << edge;
  }
}

// The join around beta = 1: continuous in value, slope and curvature at its edges,
// f = 0 at the JKR equilibrium beta = 1 (a quintic through the edge jets alone
// missed it by 2e-7 for k = 0.02 and by 5e-3 for k = 0.1), and decreasing
// throughout (the crack speed keeps the sign of 1 - beta).
TEST(CrackLaw, JoinAtEquilibrium) {
  const double w = crack_smoothing_width;
  for (double k : {0.02, 0.1, 0.5}) {
    EXPECT_EQ(crack_speed_function(1.0, k).value, 0.0) << k;
    for (double edge : {1.0 - w, 1.0 + w}) {
      const double inward = edge < 1.0 ? 1.0 : -1.0;
      // Value and slope 1e-12 either side of the edge: they differ by 2e-12 times the
      // next derivative (|f'| < 30, |f''| < 1e6 here), which sets the tolerances.
      const double eps = 1e-12;
      const auto in = crack_speed_function(edge + inward * eps, k), out = crack_speed_function(edge - inward * eps, k);
      EXPECT_NEAR(in.value, out.value, 3 * eps * std::abs(out.derivative)) << k << " " << edge;
      EXPECT_NEAR(in.derivative, out.derivative, 1e-5 * std::abs(out.derivative)) << k << " " << edge;
      // Curvature at the edge from each side: central differences of the analytic
      // slope (h = 1e-8) at 2h and 4h from the edge, extrapolated linearly to it
      // (error ~ 8 h^2 times the fourth derivative: 1e-4 relative at most here).
      const double h = 1e-8;
      auto curvature = [&](double x) {
        return (crack_speed_function(x + h, k).derivative - crack_speed_function(x - h, k).derivative) / (2 * h);
      };
      auto edge_curvature = [&](double side) {
        return 2.0 * curvature(edge + side * 2 * h) - curvature(edge + side * 4 * h);
      };
      const double c_in = edge_curvature(inward), c_out = edge_curvature(-inward);
      EXPECT_NEAR(c_in, c_out, 1e-3 * std::abs(c_out)) << k << " " << edge;
    }
    for (int i = -1000; i <= 1000; ++i) {
      const double beta = 1.0 + 1.05 * w * i / 1000.0;
      EXPECT_LT(crack_speed_function(beta, k).derivative, 0.0) << k << " " << beta;
    }
  }
}

// The DEM's table of (17): against crack_speed_function over the whole range (k, 1/k), densely
// and on a log scale towards every special point (k, 1, 1/k), for k = 0.02 and others (the
// cells are the reference law's, carried to k as crack_speed_function carries it).
TEST(CrackSpeedTable, MatchesTheCrackLaw) {
  for (double k : {0.02, 0.05, 0.5}) {
    const CrackSpeedTable table(k);
    double value_error = 0.0, slope_error = 0.0;
    auto check = [&](double beta) {
      const CrackSpeed exact = crack_speed_function(beta, k), fast = table(beta);
      if (exact.value == 0.0) {
        EXPECT_EQ(fast.value, 0.0) << beta;
        return;
      }
      value_error = std::max(value_error, std::abs(fast.value / exact.value - 1.0));
      slope_error = std::max(slope_error, std::abs(fast.derivative / exact.derivative - 1.0));
    };
    for (int i = 1; i < 200000; i++) check(k + (1.0 / k - k) * i / 200000.0);
    for (double d = 1e-13; d < 0.5; d *= 1.0001) {
      check(k * (1.0 + d));
      check(1.0 - d);
      check(1.0 + d);
      check((1.0 - d) / k);
    }
    // A cubic Hermite cell of relative width 1/32 on x^p misses f by (1/32)^4 |p (p-1) (p-2)
    // (p-3)| / 384 = 5.4e-10 for p = 1.116 (measured 6.0e-10: (17)'s linear factor), and f' by
    // a few times that over the cell's relative width, 32 (measured 5.3e-8).
    EXPECT_LT(value_error, 1e-9) << k;
    EXPECT_LT(slope_error, 1e-7) << k;
    std::printf("k = %g: largest relative error of f %.2e, of f' %.2e\n", k, value_error, slope_error);
  }
}

// f never increases with beta, on the whole domain k < beta < (1 - margin)/k, for k across the
// range `k` accepts: the crack step's search for a shrinking neck relies on it (on the branch
// where beta rises with a, the residual a - base - h c f(beta(a)) then rises with a: one root at
// most). Checked on 200 000 points spaced evenly in log beta (the joins at 0.3, 1 and 3.65 are
// 1e-2 to 1e-1 wide, hundreds of points each), the law and the DEM's table alike.
TEST(CrackLaw, NeverIncreasesWithBeta) {
  for (double k : {1e-9, 1e-4, 1e-2, 0.02, 0.05, 0.1, 0.3, 0.5, 0.9, 0.99}) {
    const CrackSpeedTable table(k);
    const double lo = std::log(k * (1.0 + 1e-12)), hi = std::log((1.0 - krijt_break_margin) / k);
    double last = crack_speed_function(std::exp(lo), k).value, last_table = table(std::exp(lo)).value;
    for (int i = 1; i <= 200000; i++) {
      const double beta = std::exp(lo + (hi - lo) * i / 200000.0);
      const CrackSpeed f = crack_speed_function(beta, k), t = table(beta);
      ASSERT_LE(f.derivative, 0.0) << "k " << k << " beta " << beta;
      ASSERT_LE(f.value, last) << "k " << k << " beta " << beta;
      ASSERT_LE(t.derivative, 0.0) << "table, k " << k << " beta " << beta;
      ASSERT_LE(t.value, last_table) << "table, k " << k << " beta " << beta;
      last = f.value;
      last_table = t.value;
    }
  }
}

// Where the reference law is (16) alone (beta_r < 0.29 or > 3.7), the law at any k is (16) at that
// k: (16) depends on beta and k only through beta and y, which the carrying keeps. Rounding in
// 1 - c (1 - beta) and its inverse moves y by a few ulps; (16)'s log L = ln(1/y) turns that into
// ~1e-16 / L of f, which grows towards the ends (L -> 0 as beta -> k or 1/k): 1e-14 (1 + 1/L).
TEST(CrackLaw, SixteenAtAnyK) {
  for (double k : {1e-6, 0.005, 0.1, 0.5, 0.9}) {
    for (double beta = 1.0001 * k; beta < 0.9999 / k; beta *= 1.01) {
      const double beta_ref = reference_beta(beta, k).beta;
      if (beta_ref > 0.29 && beta_ref < 3.7) continue;
      const CrackSpeed f = crack_speed_function(beta, k), h = crack_speed_high(beta, k);
      const double l = std::log((1.0 - k) / (beta < 1.0 ? 1.0 - beta : 1.0 - 1.0 / beta));
      const double tolerance = 1e-14 * (1.0 + 1.0 / l);
      EXPECT_NEAR(f.value, h.value, tolerance * std::abs(h.value)) << k << " " << beta;
      EXPECT_NEAR(f.derivative, h.derivative, 10 * tolerance * std::abs(h.derivative)) << k << " " << beta;
    }
  }
}

// Continuous in k: across K13's k = 0.02 (where the law used to switch from (16) and (17) to
// (16) alone) f moves by ~1e-7 times its k-derivative, which is O(f / (1 - beta)) away from the
// ends and grows towards them (the poles at k and 1/k move with k): within 1e-5 of f for beta
// from 0.03 to 20 (1/k = 50) and k moved by 1e-7. At k = 0.02 it is K13's
// law itself (PrintedFormulas: (17) exactly at beta = 0.5).
TEST(CrackLaw, ContinuousInK) {
  for (double beta = 0.03; beta < 20.0; beta *= 1.003) {
    if (std::abs(beta - 1.0) < 1e-3) continue;  // f -> 0: compare where it is not
    const double at = crack_speed_function(beta, 0.02).value;
    for (double k : {0.02 - 1e-7, 0.02 + 1e-7}) {
      EXPECT_NEAR(crack_speed_function(beta, k).value, at, 1e-5 * std::abs(at)) << k << " " << beta;
    }
  }
}

// crack_speed_concave's claim, checked: f'' <= 0 (a central difference of the analytic slope,
// h = 1e-6 (beta - 1), truncation ~1e-12 of the curvature) wherever it says so, for k across
// what `k` accepts. The crack step's Newton from a_old relies on it.
TEST(CrackLaw, ConcaveWhereDeclared) {
  int checked = 0;
  for (double k : {1e-9, 1e-4, 0.005, 0.02, 0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    for (double beta = 1.0 + 1e-6; beta < 1.0 / k; beta *= 1.0 + 2e-4) {
      if (!crack_speed_concave(beta, k)) continue;
      const double h = 1e-6 * (beta - 1.0);
      const double curvature =
          (crack_speed_function(beta + h, k).derivative - crack_speed_function(beta - h, k).derivative) / (2 * h);
      ASSERT_LE(curvature, 0.0) << k << " " << beta;
      ASSERT_LT(crack_speed_function(beta, k).derivative, 0.0) << k << " " << beta;
      checked++;
    }
  }
  EXPECT_GT(checked, 40000);
}

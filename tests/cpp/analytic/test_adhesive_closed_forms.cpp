// Closed forms for adhesive and plastic collisions: K13 (22)-(33), BP04 (8.94)-(8.101).
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include "bounce/analytic/adhesive.hpp"
#include "bounce/contact/jkr.hpp"

using namespace bounce;
using namespace bounce::analytic;

TEST(AdhesiveClosedForms, PrintedConstantsAreTheExactOnesRounded) {
  // K13 (25): 14.18 / 2 is the exact elastic JKR loss 7.09220 rounded.
  EXPECT_NEAR(jkr_collision_loss_constant(), 7.0921959719, 1e-9);
  EXPECT_NEAR(14.18 / 2.0, jkr_collision_loss_constant(), 0.005);
  // K13 (28): 10.2 is pi^5 / 30 = 10.2007 (yield at the maximal Hertz overlap).
  EXPECT_NEAR(yield_velocity_constant(), 10.2, 0.005);
  // K13 (26): 5.57 is 2 b (15/8) t0 = 5.5679.
  EXPECT_NEAR(cor_viscous_constant(), 5.57, 0.005);
  // The loss scales as (gamma^5 R^4 / E*^2)^{1/3}.
  EXPECT_NEAR(jkr_collision_loss(2e-6, 3e9, 0.3) / std::cbrt(std::pow(0.3, 5) * std::pow(2e-6, 4) / 9e18),
              jkr_collision_loss_constant(), 1e-9);
}

TEST(AdhesiveClosedForms, YieldVelocityIsWherePressureReachesYield) {
  // K13 (28) with the exact constant: at v_y the central Hertz pressure at the maximal
  // overlap, p0 = (2 E*/(pi R)) l with l of (33), equals p_y = 1.6 Y.
  const double r = 1e-3, m = 1e-5, e = 1e11, y = 1e9;
  const double v_y = yield_velocity(r, m, e, y) * std::sqrt(yield_velocity_constant() / 10.2);
  const double p0 = 2.0 * e / (std::numbers::pi * r) * plastic_length_scale(m, v_y, r, e);
  EXPECT_NEAR(p0 / (1.6 * y), 1.0, 1e-12);
}

TEST(AdhesiveClosedForms, ThorntonNing) {
  EXPECT_EQ(cor_thornton_ning(0.5, 1.0), 1.0);                       // below yield: elastic
  EXPECT_NEAR(cor_thornton_ning(1.0, 1.0), 1.0, 1e-4);              // continuous at v = v_y (4 printed digits)
  // Far above yield e_P -> (6 sqrt3/5)^{1/2} (vhat / (2 sqrt(6/5)))^{1/4} ~ vhat^{1/4}.
  const double vhat = 1e-4;
  EXPECT_NEAR(cor_thornton_ning(1.0 / vhat, 1.0) /
                  (std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::pow(vhat / (2.0 * std::sqrt(1.2)), 0.25)),
              1.0, 1e-4);
  EXPECT_NEAR(cor_with_plastic(0.9, 0.8), std::sqrt(0.81 + 0.64 - 1.0), 1e-15);  // (30)
  EXPECT_EQ(cor_with_plastic(0.5, 0.5), 0.0);                                     // negative radicand: stick
  EXPECT_NEAR(cor_independent(0.99, 0.95), std::sqrt(0.9801 + 0.9025 - 1.0), 1e-15);  // (27)
}

// BP04 (8.94)-(8.96): the work of the tensile force from a0 to a_sep, by quadrature of
// F(a) dxi/da with (8.48)-(8.49) (R = 2 R_eff), equals the closed form.
TEST(AdhesiveClosedForms, TensileWorkByQuadrature) {
  const double r_eff = 0.7e-6, e_star = 3.7e9, gamma = 0.37;
  const double d = 3.0 / (4.0 * e_star), r = 2.0 * r_eff;
  const double a0 = contact::jkr::bp04::zero_load_contact_radius(d, gamma, r);
  const double a_sep = contact::jkr::bp04::separation_contact_radius(d, gamma, r);
  auto integrand = [&](double a) {
    const double h = 1e-7 * a;  // d xi / da by central differences of (8.48): error ~1e-14 relative
    const double dxi = (contact::jkr::bp04::compression(d, gamma, r, a + h) - contact::jkr::bp04::compression(d, gamma, r, a - h)) / (2 * h);
    return contact::jkr::bp04::force(d, gamma, r, a) * dxi;
  };
  const double w = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, a0, a_sep, 10, 1e-13);
  EXPECT_NEAR(w / tensile_work(r_eff, e_star, gamma), 1.0, 1e-8);
  EXPECT_NEAR(tensile_work_constant(), 0.1 * (3.0 * std::cbrt(2.0) - 1.0) * std::pow(3.0, 2.0 / 3.0), 1e-15);
  // (8.98): with the work just balancing the kinetic energy, e_ad = 0.
  EXPECT_EQ(cor_adhesive_bp04(0.9, 1.0, 0.5 * 0.81 * 2.0, 2.0), 0.0);
}

TEST(AdhesiveClosedForms, QuasiStaticLimits) {
  EXPECT_DOUBLE_EQ(bulk_quasi_static_limit(0.25, 1e-8), 1e-2 * 0.0625 * 1e-8);            // (A.2)
  EXPECT_DOUBLE_EQ(crack_quasi_static_limit(2e-10, 1e-7, 3.7e9, 0.37, 1e-8),               // (A.4)
                   1e-3 * (2e-10 / 1e-7) * (2.0 * 3.7e9 * 2e-10 / 0.37) * 1e-8);
  EXPECT_NEAR(hall_petch_yield(1e8, 1e5, 1e-6), 1e8 + 1e5 / 1e-3, 1e-3);                 // (32)
}

// General convex bodies, BP04 (8.6)-(8.21), against Hertz and independent quadrature.
#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <gtest/gtest.h>

#include "bounce/contact/convex.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/mixing.hpp"

using namespace bounce;

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double pi = std::numbers::pi;

// Independent evaluation of (8.15), (8.16) by double-exponential quadrature on
// [0, inf) after t = u^2 (removes the t^{-1/2} endpoint singularity).
double n_by_quadrature(double x) {
  boost::math::quadrature::exp_sinh<double> integrator;
  return integrator.integrate(
      [x](double u) { return 2.0 / std::sqrt((1.0 + x * u * u) * (1.0 + u * u)); }, 1e-14);
}
double m_by_quadrature(double x) {
  boost::math::quadrature::exp_sinh<double> integrator;
  return integrator.integrate(
      [x](double u) {
        const double w = 1.0 + u * u;
        return 2.0 / (w * std::sqrt(w * (1.0 + x * u * u)));
      },
      1e-14);
}
}  // namespace

TEST(Convex, SpheresReproduceHertzTo1e12) {
  const double e_star = effective_modulus(7e9, 0.25, 190e9, 0.28);
  const double d = hertz_compliance_d(e_star);
  for (auto [r1, r2] : {std::pair{1e-6, 1e-6}, std::pair{1e-6, 3.7e-6}, std::pair{2e-3, inf}}) {
    for (double angle : {0.0, 0.7, pi / 2}) {
      const auto c = contact::convex::solve({r1, r1, r2, r2, angle}, d);
      const double r_eff = effective_radius(r1, r2);
      EXPECT_EQ(c.x0, 1.0);
      EXPECT_NEAR(c.n_x0, pi, 1e-15 * pi);      // BP04: N(1) = pi
      EXPECT_NEAR(c.m_x0, pi / 2, 1e-15 * pi);  // BP04: M(1) = pi/2
      const double rho = hertz_constant(e_star, r_eff);
      EXPECT_NEAR(c.force_constant / rho, 1.0, 1e-12);
      const double overlap = 1e-3 * r_eff;
      const auto ellipse = contact::convex::ellipse(c, d, overlap);
      const double a = contact::hertz::contact_radius(r_eff, overlap);
      EXPECT_NEAR(ellipse.semi_axis_a / a, 1.0, 1e-12);
      EXPECT_NEAR(ellipse.semi_axis_b / a, 1.0, 1e-12);
      EXPECT_NEAR(contact::convex::force(c, overlap) / contact::hertz::force(rho, overlap), 1.0, 1e-12);
    }
  }
}

// Crossed cylinders of equal radius (phi = 90 deg) touch like a sphere of radius R on
// a flat: B1 = B2 = 1/(2R). This exercises the angle term of (8.7).
TEST(Convex, CrossedCylindersActLikeSphereOnFlat) {
  const double R = 2e-3;
  const auto form = contact::convex::quadratic_form({R, inf, R, inf, pi / 2});
  EXPECT_NEAR(form.b1, 0.5 / R, 1e-12 / R);
  EXPECT_NEAR(form.b2, 0.5 / R, 1e-9 / R);
  // Parallel cylinders (phi = 0) make a line contact: outside the theory.
  EXPECT_THROW((void)contact::convex::quadratic_form({R, inf, R, inf, 0.0}), InvalidArgument);
}

TEST(Convex, NAndMAgreeWithQuadrature) {
  // Carlson forms vs quadrature to 1e-12: both are accurate to ~1e-14, so 1e-12 leaves margin.
  for (double x : {1e-4, 0.01, 0.1, 0.37, 1.0, 2.5, 10.0, 1e3}) {
    EXPECT_NEAR(contact::convex::n_function(x) / n_by_quadrature(x), 1.0, 1e-12) << x;
    EXPECT_NEAR(contact::convex::m_function(x) / m_by_quadrature(x), 1.0, 1e-12) << x;
  }
}

TEST(Convex, AxisRatioAgreesWithQuadratureRoot) {
  for (double ratio : {0.95, 0.5, 0.1, 0.01}) {
    const double x0 = contact::convex::axis_ratio_squared({1.0, ratio});
    // Independent root: bisection on (8.18) with the quadrature N, M (60 halvings of
    // log x over [-40, 0] resolve x0 to ~1e-16 relative; the quadrature error
    // 1e-14 of M moves the root by about that over d ln r / d ln x ~ 0.5, so 1e-11 is safe).
    double lo = -40.0, hi = 0.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      const double x = std::exp(mid);
      const double r = std::sqrt(x) * m_by_quadrature(1.0 / x) / m_by_quadrature(x);
      (r < ratio ? lo : hi) = mid;
    }
    EXPECT_NEAR(x0 / std::exp(0.5 * (lo + hi)), 1.0, 1e-11) << ratio;
    EXPECT_LT(x0, 1.0);
  }
}

TEST(Convex, EllipseIsConsistentWith8_19And8_20) {
  // A triaxial pair: check (8.19)-(8.20) hold for the returned semi-axes and force.
  const double d = hertz_compliance_d(effective_modulus(70e9, 0.345, 70e9, 0.345));
  const auto c = contact::convex::solve({1e-3, 4e-3, 2e-3, inf, 0.4}, d);
  const double xi = 1e-7;
  const auto e = contact::convex::ellipse(c, d, xi);
  const double f = contact::convex::force(c, xi);
  const double b = e.semi_axis_b;
  EXPECT_NEAR(xi, f * d / pi * c.n_x0 / b, 1e-13 * xi);                                // (8.19)
  EXPECT_NEAR(c.form.b1, f * d / pi * c.m_x0 / (c.x0 * b * b * b), 1e-12 * c.form.b1);  // (8.20)
  EXPECT_NEAR(c.form.b2,
              f * d / pi * contact::convex::m_function(1.0 / c.x0) / (e.semi_axis_a * b * b),
              1e-10 * c.form.b2);  // (8.13)
}

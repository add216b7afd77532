// Lennard-Jones surface forces, the Hamaker relation and the Tabor parameters.
#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/tools/minima.hpp>
#include <gtest/gtest.h>

#include "bounce/contact/surface_forces.hpp"

using namespace bounce::contact::surface;

// BP04 (8.54): the work to separate two half-spaces from z0 to infinity against the
// pressure (8.53) is gamma. Quadrature to 1e-14; the integrand is smooth on [z0, inf).
TEST(SurfaceForces, HamakerRelation) {
  const double hamaker = 1e-19, z0 = 0.3e-9;
  boost::math::quadrature::exp_sinh<double> integrator;
  // h = z0 (1 + u): dimensionless integral, then scaled back.
  const double work = -z0 * integrator.integrate(
                                [&](double u) { return lennard_jones_pressure(hamaker, z0, z0 * (1.0 + u)); },
                                1e-14);
  EXPECT_NEAR(work / surface_energy_from_hamaker(hamaker, z0), 1.0, 1e-12);
  EXPECT_NEAR(hamaker_from_surface_energy(surface_energy_from_hamaker(hamaker, z0), z0) / hamaker,
              1.0, 1e-15);
  EXPECT_NEAR(lennard_jones_pressure(hamaker, z0, z0), 0.0, 1e-30);  // equilibrium at z0
}

TEST(SurfaceForces, PeakTension) {
  const double gamma = 0.37, z0 = 0.2e-9;
  const double hamaker = hamaker_from_surface_energy(gamma, z0);
  std::uintmax_t iterations = 200;
  // Brent in units of z0 (its tolerance has an absolute floor).
  auto [u, p] = boost::math::tools::brent_find_minima(
      [&](double x) { return lennard_jones_pressure(hamaker, z0, x * z0); }, 1.0, 3.0,
      std::numeric_limits<double>::digits / 2, iterations);
  EXPECT_NEAR(-p / lennard_jones_max_tension(gamma, z0), 1.0, 1e-12);
  EXPECT_NEAR(u / std::pow(3.0, 1.0 / 6.0), 1.0, 1e-6);
}

TEST(SurfaceForces, TaborParameters) {
  const double R = 0.5e-6, e = 3.7e9, gamma = 0.37, z0 = 0.2e-9;
  const double mu = tabor_parameter(R, e, gamma, z0);
  EXPECT_NEAR(mu, std::cbrt(R * gamma * gamma / (e * e * z0 * z0 * z0)), 1e-15 * mu);
  // docs/decisions.md D3: BP04's (8.55) is smaller than K13's (11) by 4^{1/3}.
  EXPECT_NEAR(mu / tabor_parameter_bp04(R, e, gamma, z0), std::cbrt(4.0), 1e-14);
  // lambda = 2 sigma0 (9R/(16 pi gamma E*^2))^{1/3} with sigma0 = 16 gamma/(9 sqrt3 z0):
  // lambda / mu = (32/(9 sqrt 3)) (9/(16 pi))^{1/3} = 1.15705...
  EXPECT_NEAR(maugis_parameter(R, e, gamma, z0) / mu,
              32.0 / (9.0 * std::sqrt(3.0)) * std::cbrt(9.0 / (16.0 * std::numbers::pi)), 1e-14);
  EXPECT_EQ(regime_k13(6.0), "jkr");
  EXPECT_EQ(regime_k13(0.05), "dmt");
  EXPECT_EQ(regime_k13(1.0), "transition");
  EXPECT_EQ(regime_bp04(5e-3), "dmt");
  EXPECT_EQ(regime_bp04(5.0), "jkr");
  EXPECT_EQ(regime_bp04(20.0), "jump-into-contact");
}

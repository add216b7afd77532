// K13 (1)-(3), (14): a and delta as independent variables.
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss.hpp>
#include <gtest/gtest.h>

#include "bounce/contact/hertz.hpp"
#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"

using namespace bounce;

namespace {
const contact::independent::Geometry g{0.5e-6, 3.7e9};
// States away from a^2 = R delta (where dU/da vanishes), including negative delta.
const std::pair<double, double> states[] = {
    {5e-8, 1e-9}, {7e-8, 3e-9}, {3e-8, -2e-9}, {1e-7, 1e-8}, {2e-8, 5e-9}};
}  // namespace

TEST(Independent, ForceIsDerivativeOfEnergyInDelta) {
  for (auto [a, delta] : states) {
    // U_E is quadratic in delta: the central difference has no truncation error, only
    // round-off ~ eps U / h = 1e-16 / 1e-4 relative -> 1e-10 is a safe bound.
    const double h = 1e-4 * std::abs(delta);
    const double fd = (contact::independent::elastic_energy(g, a, delta + h) -
                       contact::independent::elastic_energy(g, a, delta - h)) / (2.0 * h);
    const double f = contact::independent::elastic_force(g, a, delta);
    EXPECT_NEAR(fd, f, 1e-10 * std::abs(f)) << a << " " << delta;
  }
}

TEST(Independent, EnergyReleaseIsDerivativeOfEnergyInA) {
  for (auto [a, delta] : states) {
    // Central difference of a quintic in a: truncation (h^2/6) U''' ~ 1e-8 relative for
    // h = 1e-4 a; round-off ~ 1e-12. Bound 1e-7.
    const double h = 1e-4 * a;
    const double fd = (contact::independent::elastic_energy(g, a + h, delta) -
                       contact::independent::elastic_energy(g, a - h, delta)) / (2.0 * h);
    const double release = 2.0 * std::numbers::pi * a * contact::independent::effective_surface_energy(g, a, delta);
    EXPECT_NEAR(fd, release, 1e-7 * std::abs(release)) << a << " " << delta;
  }
}

TEST(Independent, PressureIntegratesToForce) {
  for (auto [a, delta] : states) {
    // r = a (1 - u^2) cancels the 1/sqrt(a - r) edge singularity against dr = -2au du:
    // the integrand is analytic on [0, 1], so 30-point Gauss-Legendre is exact to
    // round-off. The round-off of a - r is eps/u^2 relative; the smallest node is
    // u = 1.6e-3 with weight 4e-3, so it contributes ~2e-13: bound 1e-11.
    // Copies under their own names: clang 14 cannot capture a structured binding, and clang 19
    // warns (-Wshadow) when a copy keeps the binding's name.
    auto integrand = [&, radius = a, approach = delta](double u) {
      const double r = radius * (1.0 - u * u);
      return 2.0 * std::numbers::pi * r * contact::independent::pressure(g, radius, approach, r) * 2.0 * radius * u;
    };
    const double f = boost::math::quadrature::gauss<double, 30>::integrate(integrand, 0.0, 1.0);
    EXPECT_NEAR(f, contact::independent::elastic_force(g, a, delta),
                1e-11 * std::abs(contact::independent::elastic_force(g, a, delta)));
  }
}

TEST(Independent, HertzAndJkrAreItsEquilibria) {
  // K13 (4): dU_E/da = 0 at a^2 = R delta, and (2) then gives (5).
  const double delta = 2e-9;
  const double a = contact::hertz::contact_radius(g.effective_radius, delta);
  EXPECT_NEAR(contact::independent::effective_surface_energy(g, a, delta), 0.0, 1e-20);
  EXPECT_NEAR(contact::independent::elastic_force(g, a, delta),
              contact::hertz::force_from_contact_radius(g.effective_modulus, g.effective_radius, a),
              1e-12 * contact::hertz::force_from_contact_radius(g.effective_modulus, g.effective_radius, a));
  // K13 (7)-(8): on the JKR curve G_eff = gamma.
  const contact::jkr::Parameters p{g.effective_radius, g.effective_modulus, 0.37};
  for (double aj : {2e-8, 5e-8, 9e-8}) {
    EXPECT_NEAR(contact::independent::effective_surface_energy(g, aj, contact::jkr::overlap(p, aj)), 0.37, 1e-12);
    EXPECT_NEAR(contact::independent::elastic_force(g, aj, contact::jkr::overlap(p, aj)), contact::jkr::force(p, aj),
                1e-12 * std::abs(contact::jkr::pull_off_force(p)));
  }
}

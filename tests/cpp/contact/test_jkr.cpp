// JKR in K13's and BP04's notations; pull-off; inverses.
#include <cmath>
#include <limits>
#include <numbers>

#include <boost/math/tools/minima.hpp>
#include <gtest/gtest.h>

#include "bounce/contact/jkr.hpp"
#include "bounce/pair/materials_table.hpp"
#include "bounce/pair/pair.hpp"

using namespace bounce;

namespace {
constexpr double pi = std::numbers::pi;

// An unlike pair: 1 um ice on a 3 um steel sphere.
Pair unlike_pair() {
  const auto& t = MaterialTable::builtin();
  return Pair(sphere(t.at("water-ice"), 1e-6), sphere(t.at("steel"), 3e-6));
}
contact::jkr::Parameters parameters(const Pair& pair) {
  return {pair.effective_radius(), pair.effective_modulus(), *pair.surface_energy()};
}
}  // namespace

// BP04's formulas are written for identical spheres of radius R; with R -> 2 R_eff they
// must agree with K13's for any pair. Both are closed forms evaluated in a different
// order, so they agree to a few ulps: 1e-13 relative (absolute on the scale |F_c| where
// the force crosses zero).
TEST(Jkr, Bp04AndK13AgreeForUnlikePairs) {
  const Pair pair = unlike_pair();
  const auto p = parameters(pair);
  const double d = pair.hertz_compliance_d();
  const double gamma = p.surface_energy;
  const double R = 2.0 * p.effective_radius;
  const double f_scale = std::abs(contact::jkr::pull_off_force(p));
  for (double a : {1e-9, 2e-8, 5e-8, 1e-7, 3e-7}) {
    EXPECT_NEAR(contact::jkr::bp04::force(d, gamma, R, a), contact::jkr::force(p, a),
                1e-13 * (std::abs(contact::jkr::force(p, a)) + f_scale));
    EXPECT_NEAR(contact::jkr::bp04::compression(d, gamma, R, a), contact::jkr::overlap(p, a),
                1e-13 * (std::abs(contact::jkr::overlap(p, a)) + std::abs(contact::jkr::separation_overlap(p))));
    // (8.44)-(8.46): F = F_H - F_B with the Boussinesq force.
    EXPECT_NEAR(4.0 * p.effective_modulus * a * a * a / (3.0 * p.effective_radius) +
                    contact::jkr::bp04::boussinesq_force(d, gamma, a),
                contact::jkr::force(p, a), 1e-13 * (std::abs(contact::jkr::force(p, a)) + f_scale));
  }
  for (double f : {-0.9 * f_scale, 0.0, 2.0 * f_scale, 100.0 * f_scale}) {
    EXPECT_NEAR(contact::jkr::bp04::contact_radius(d, gamma, R, f) / contact::jkr::contact_radius_from_force(p, f),
                1.0, 1e-13);
  }
  EXPECT_NEAR(contact::jkr::bp04::zero_load_contact_radius(d, gamma, R) / contact::jkr::equilibrium_contact_radius(p),
              1.0, 1e-14);
  EXPECT_NEAR(contact::jkr::bp04::separation_force(gamma, R) / contact::jkr::pull_off_force(p), 1.0, 1e-15);
  EXPECT_NEAR(contact::jkr::bp04::separation_contact_radius(d, gamma, R) / contact::jkr::pull_off_contact_radius(p),
              1.0, 1e-14);
}

TEST(Jkr, PullOffIsMinusThreeHalvesPiGammaR) {
  const auto p = parameters(unlike_pair());
  // Minimise F(a) numerically (Brent to digits/2 = 26 bits, its maximum: the abscissa
  // to ~1e-8, so at a quadratic minimum the force to ~1e-15); compare to 1e-12.
  // Boost's Brent has an absolute tolerance floor, so minimise in units of a_eq.
  const double scale = contact::jkr::equilibrium_contact_radius(p);
  std::uintmax_t iterations = 200;
  auto [u_min, f_min] = boost::math::tools::brent_find_minima(
      [&](double u) { return contact::jkr::force(p, u * scale); }, 1e-3, 10.0,
      std::numeric_limits<double>::digits / 2, iterations);
  const double a_min = u_min * scale;
  EXPECT_NEAR(f_min / (-1.5 * pi * p.surface_energy * p.effective_radius), 1.0, 1e-12);
  EXPECT_NEAR(a_min / contact::jkr::pull_off_contact_radius(p), 1.0, 1e-6);  // flat minimum: a to sqrt(eps)
  EXPECT_NEAR(contact::jkr::force(p, contact::jkr::equilibrium_contact_radius(p)), 0.0, 1e-13 * std::abs(f_min));
}

TEST(Jkr, SeparationUnderDisplacementControl) {
  const auto p = parameters(unlike_pair());
  const double scale = contact::jkr::equilibrium_contact_radius(p);  // Brent in units of a_eq
  std::uintmax_t iterations = 200;
  auto [u_min, delta_min] = boost::math::tools::brent_find_minima(
      [&](double u) { return contact::jkr::overlap(p, u * scale); }, 1e-3, 10.0,
      std::numeric_limits<double>::digits / 2, iterations);
  const double a_min = u_min * scale;
  const double closed = -0.75 * std::cbrt(pi * pi * p.surface_energy * p.surface_energy *
                                          p.effective_radius /
                                          (p.effective_modulus * p.effective_modulus));
  EXPECT_NEAR(delta_min / closed, 1.0, 1e-12);
  EXPECT_NEAR(contact::jkr::separation_overlap(p) / closed, 1.0, 1e-14);
  EXPECT_NEAR(a_min / contact::jkr::separation_contact_radius(p), 1.0, 1e-6);
}

TEST(Jkr, InversesOnTheStableBranches) {
  const auto p = parameters(unlike_pair());
  for (double factor : {1.0, 1.01, 1.5, 3.0, 20.0}) {
    const double a = factor * contact::jkr::pull_off_contact_radius(p);
    EXPECT_NEAR(contact::jkr::contact_radius_from_force(p, contact::jkr::force(p, a)) / a, 1.0, 1e-7 / factor);
    const double b = factor * contact::jkr::separation_contact_radius(p);
    EXPECT_NEAR(contact::jkr::contact_radius_from_overlap(p, contact::jkr::overlap(p, b)) / b, 1.0, 1e-7 / factor);
  }
}

TEST(Jkr, EnergyIsStationaryOnTheCurve) {
  // d(U_E + U_S)/da = 0 at fixed delta (K13 (7)); along the curve the force is
  // d(U_E + U_S)/d delta, so dU_total/da = F d delta/da (chain rule), checked by FD.
  const auto p = parameters(unlike_pair());
  for (double a : {3e-8, 6e-8, 1.2e-7}) {
    const double h = 1e-5 * a;
    const double du = (contact::jkr::total_energy(p, a + h) - contact::jkr::total_energy(p, a - h)) / (2.0 * h);
    const double ddelta = (contact::jkr::overlap(p, a + h) - contact::jkr::overlap(p, a - h)) / (2.0 * h);
    EXPECT_NEAR(du, contact::jkr::force(p, a) * ddelta, 1e-7 * std::abs(contact::jkr::pull_off_force(p) * ddelta));
  }
}

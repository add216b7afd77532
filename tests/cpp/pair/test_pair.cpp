// Pair quantities and mixing rules (docs/decisions.md D1, D2).
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "bounce/core/error.hpp"
#include "bounce/pair/materials_table.hpp"
#include "bounce/pair/mixing.hpp"
#include "bounce/pair/pair.hpp"

using namespace bounce;

namespace {
const Material& ice() { return MaterialTable::builtin().at("water-ice"); }
const Material& steel() { return MaterialTable::builtin().at("steel"); }
constexpr double inf = std::numeric_limits<double>::infinity();
}  // namespace

TEST(Mixing, ClosedForms) {
  EXPECT_DOUBLE_EQ(effective_radius(1.0, 3.0), 0.75);
  EXPECT_DOUBLE_EQ(effective_radius(2.0, inf), 2.0);
  EXPECT_DOUBLE_EQ(effective_mass(2.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(effective_mass(2.0, inf), 2.0);
  // Identical materials: E* = E / (2 (1 - nu^2)); rigid body 2: E / (1 - nu^2).
  EXPECT_DOUBLE_EQ(effective_modulus(7e9, 0.25, 7e9, 0.25), 7e9 / (2.0 * (1.0 - 0.0625)));
  EXPECT_DOUBLE_EQ(effective_modulus(7e9, 0.25, inf, 0.3), 7e9 / (1.0 - 0.0625));
  // BSHP96 (14) and BP04 (8.24): rho = 2Y/(3(1-nu^2)) sqrt(R_eff) for like materials.
  const double e_star = effective_modulus(10e9, 0.3, 10e9, 0.3);
  EXPECT_NEAR(hertz_constant(e_star, 0.5e-2), 2.0 * 10e9 / (3.0 * 0.91) * std::sqrt(0.5e-2),
              1e-15 * hertz_constant(e_star, 0.5e-2));
  EXPECT_DOUBLE_EQ(hertz_compliance_d(e_star), 0.75 * 2.0 * 0.91 / 10e9);
  EXPECT_DOUBLE_EQ(combined_surface_energy(0.37, 0.37), 0.37);
  EXPECT_DOUBLE_EQ(combined_surface_energy(0.04, 1.0), 0.2);
}

TEST(Mixing, TangentialMassFactorBshp96Eq8) {
  // Identical solid spheres: kappa = 2/7 (BSHP96 §III).
  EXPECT_NEAR(tangential_mass_factor(1.0, 0.4, 1.0, 0.4), 2.0 / 7.0, 1e-15);
  // Sphere on a wall: kappa^-1 = 1 + 1/J = 7/2.
  EXPECT_NEAR(tangential_mass_factor(1.0, 0.4, inf, 0.4), 2.0 / 7.0, 1e-15);
  // Unequal grains: (8) equals the direct form 1/(m_eff kappa) = 1/m_eff + 1/(J1 m1) + 1/(J2 m2).
  const double m1 = 2.0, m2 = 5.0, j1 = 0.4, j2 = 2.0 / 3.0;
  const double m_eff = m1 * m2 / (m1 + m2);
  const double direct = 1.0 / (m_eff * (1.0 / m_eff + 1.0 / (j1 * m1) + 1.0 / (j2 * m2)));
  EXPECT_NEAR(tangential_mass_factor(m1, j1, m2, j2), direct, 1e-15);
}

TEST(Pair, UnlikeSpheres) {
  const Pair pair(sphere(ice(), 1e-6), sphere(steel(), 3e-6));
  EXPECT_DOUBLE_EQ(pair.effective_radius(), 0.75e-6);
  const double m1 = 4.0 / 3.0 * std::numbers::pi * 1e-18 * 1000.0;
  const double m2 = 4.0 / 3.0 * std::numbers::pi * 27e-18 * 7920.0;
  EXPECT_NEAR(pair.effective_mass(), m1 * m2 / (m1 + m2), 1e-15 * m1);
  EXPECT_NEAR(*pair.surface_energy(), std::sqrt(0.37 * 1.62), 1e-15);
  EXPECT_NEAR(pair.hertz_constant(), 4.0 / 3.0 * pair.effective_modulus() * std::sqrt(0.75e-6),
              1e-6);
}

TEST(Pair, WallDefaultsToElasticNotRigid) {
  const Pair elastic(sphere(ice(), 1e-6), wall(ice()));
  const Pair rigid(sphere(ice(), 1e-6), rigid_wall(ice()));
  EXPECT_DOUBLE_EQ(elastic.effective_radius(), 1e-6);
  EXPECT_NEAR(elastic.effective_mass(), 4.0 / 3.0 * std::numbers::pi * 1e-18 * 1000.0, 1e-30);
  EXPECT_DOUBLE_EQ(rigid.effective_modulus(), 2.0 * elastic.effective_modulus());
}

TEST(Pair, RejectsBadBodies) {
  Material m = ice();
  auto expect_error = [](const Body& b1, const Body& b2, const std::string& parameter) {
    try {
      Pair p(b1, b2);
      ADD_FAILURE() << "no error for " << parameter;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), parameter);
    }
  };
  Material bad = m;
  bad.youngs_modulus = 0.0;
  expect_error(sphere(bad, 1e-6), sphere(m, 1e-6), "body1.E");
  bad = m;
  bad.poisson_ratio = -1.0;
  expect_error(sphere(m, 1e-6), sphere(bad, 1e-6), "body2.nu");
  bad = m;
  bad.density = std::nan("");
  expect_error(sphere(bad, 1e-6), sphere(m, 1e-6), "body1.density");
  bad = m;
  bad.surface_energy = -0.1;
  expect_error(sphere(bad, 1e-6), sphere(m, 1e-6), "body1.gamma");
  expect_error(sphere(m, -1e-6), sphere(m, 1e-6), "body1.radius");
  expect_error(sphere(m, 1e-6), sphere(m, inf * 0.0), "body2.radius");
  expect_error(wall(m), sphere(m, 1e-6), "body1.radius");
}

TEST(Pair, LawWithoutGammaNamesTheMaterial) {
  const Pair pair = Pair::identical(MaterialTable::builtin().at("ceramics"), 1e-3);
  try {
    (void)pair.require_surface_energy("law jkr");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "gamma");
    EXPECT_NE(e.allowed().find("0.04-5"), std::string::npos);
  }
}

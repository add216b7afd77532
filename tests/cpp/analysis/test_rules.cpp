// Post-collision velocities and spins (BSHP96 (1)-(3), (8), (11), (42)-(43) with the
// impulse derived in rules.hpp): conservation laws to round-off for random unequal grains,
// the restitution of the contact velocity, walls, and coefficients from a model.
#include <cmath>

#include <gtest/gtest.h>

#include "model_helpers.hpp"

#include "bounce/analysis/rules.hpp"

using namespace bounce;
using namespace bounce::analysis;

namespace {

Vector3 add(const Vector3& a, const Vector3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vector3 scale(double s, const Vector3& a) { return {s * a[0], s * a[1], s * a[2]}; }
Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vector3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

struct Random {
  std::uint64_t state = 2024;
  double operator()(double lo, double hi) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11) / 9007199254740992.0;
  }
  Vector3 vector(double size) { return {(*this)(-size, size), (*this)(-size, size), (*this)(-size, size)}; }
};

Material stuff(double density) {
  Material m;
  m.name = "test";
  m.youngs_modulus = 1e9;
  m.poisson_ratio = 0.3;
  m.density = density;
  return m;
}

}  // namespace

// Random unequal grains (radius, density, moment of inertia), random geometry, motion and
// coefficients: momentum and angular momentum about the contact point are conserved to
// round-off (1e-13 of their scale), the contact velocity is restituted as BSHP96 (1)-(2)
// say, and the energy changes by BSHP96 (11).
TEST(Rules, ConservationForUnequalGrains) {
  Random rnd;
  for (int i = 0; i < 200; ++i) {
    Body b1 = sphere(stuff(rnd(500.0, 3000.0)), rnd(1e-3, 1e-2));
    Body b2 = sphere(stuff(rnd(500.0, 3000.0)), rnd(1e-3, 1e-2));
    b1.inertia_factor = rnd(0.2, 0.67);
    b2.inertia_factor = rnd(0.2, 0.67);
    const Pair pair(b1, b2);
    const Vector3 direction = rnd.vector(1.0);
    const Vector3 n = scale(1.0 / norm(direction), direction);
    GrainMotion g1{rnd.vector(2.0), rnd.vector(300.0)}, g2{rnd.vector(2.0), rnd.vector(300.0)};
    // Make them approach: flip grain 1's velocity component along n if needed.
    if (contact_velocity(pair, n, g1, g2).approaching == false) g1.velocity = add(g1.velocity, scale(-10.0, n));
    ASSERT_TRUE(contact_velocity(pair, n, g1, g2).approaching);
    const double en = rnd(0.0, 1.0), et = rnd(-1.0, 1.0);
    const auto r = apply_restitution(pair, n, g1, g2, en, et);
    const double m1 = b1.mass(), m2 = b2.mass();
    const double j1 = b1.inertia_factor * m1 * b1.radius * b1.radius, j2 = b2.inertia_factor * m2 * b2.radius * b2.radius;
    // Linear momentum.
    const Vector3 p0 = add(scale(m1, g1.velocity), scale(m2, g2.velocity));
    const Vector3 p1 = add(scale(m1, r.grain1.velocity), scale(m2, r.grain2.velocity));
    const double p_scale = m1 * norm(g1.velocity) + m2 * norm(g2.velocity);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p1[k], p0[k], 1e-13 * p_scale);
    // Angular momentum about the contact point c (centres at c + R1 n and c - R2 n).
    auto angular = [&](const GrainMotion& a, const GrainMotion& b) {
      return add(add(scale(m1, cross(scale(b1.radius, n), a.velocity)), scale(j1, a.angular_velocity)),
                 add(scale(m2, cross(scale(-b2.radius, n), b.velocity)), scale(j2, b.angular_velocity)));
    };
    const Vector3 l0 = angular(g1, g2), l1 = angular(r.grain1, r.grain2);
    const double l_scale = p_scale * (b1.radius + b2.radius) + j1 * norm(g1.angular_velocity) + j2 * norm(g2.angular_velocity);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(l1[k], l0[k], 1e-13 * l_scale);
    // BSHP96 (1), (2) at the contact.
    const auto after = contact_velocity(pair, n, r.grain1, r.grain2);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(after.normal[k], -en * r.before.normal[k], 1e-12 * (norm(r.before.normal) + norm(r.before.tangential)));
      EXPECT_NEAR(after.tangential[k], et * r.before.tangential[k], 1e-12 * (norm(r.before.normal) + norm(r.before.tangential)));
    }
    // BSHP96 (11).
    const double m = pair.effective_mass(), kappa = pair.tangential_mass_factor();
    const double gn = r.before.normal_speed, gt = r.before.tangential_speed;
    const double dq = 0.5 * m * gn * gn * (en * en - 1.0) + 0.5 * m * kappa * gt * gt * (et * et - 1.0);
    EXPECT_NEAR(r.energy_change, dq, 1e-12 * kinetic_energy(pair, g1, g2));
  }
}

// A grain on a wall: the wall does not move, the grain bounces as on an infinitely heavy
// partner (m_eff = m, kappa = J/(J + m R^2)).
TEST(Rules, Wall) {
  const Pair pair(sphere(stuff(1000.0), 0.01), wall(stuff(1000.0)));
  const GrainMotion grain{{1.0, 0.0, -2.0}, {0.0, 0.0, 0.0}}, still{};
  const auto r = apply_restitution(pair, {0.0, 0.0, 1.0}, grain, still, 0.5, -1.0);
  EXPECT_NEAR(r.grain1.velocity[2], 1.0, 1e-15);  // -0.5 * (-2)
  EXPECT_EQ(r.grain2.velocity, still.velocity);
  EXPECT_NEAR(pair.tangential_mass_factor(), 2.0 / 7.0, 1e-15);
  // eps^T = -1 (rough, elastic): the contact-point tangential velocity reverses.
  EXPECT_NEAR(contact_velocity(pair, {0.0, 0.0, 1.0}, r.grain1, r.grain2).tangential[0], -1.0, 1e-14);
}

// With a model: eps^N and eps^T computed at this encounter's g^N and g^T; smooth grains
// (no friction given) keep their tangential motion; receding grains are refused.
TEST(Rules, FromAModel) {
  const Pair pair = Pair::identical(stuff(1000.0), 0.01);
  const auto spec = bounce::testing::viscoelastic(pair, 1e-6);
  const Vector3 n{1.0, 0.0, 0.0};
  const GrainMotion g1{{-0.5, 0.3, 0.0}, {}}, g2{{0.5, 0.0, 0.0}, {}};
  const auto smooth = collide_grains(pair, spec, n, g1, g2);
  EXPECT_NEAR(smooth.cor, collide(pair, spec, 1.0).cor, 1e-12);
  EXPECT_EQ(smooth.cor_tangential, 1.0);
  const auto rough_model = bounce::testing::model(
      pair, "viscoelastic", {{"A", 1e-6}, {"friction", std::sqrt(2e-4)}, {"asperity", 2e-4 * pair.effective_radius()}});
  const auto rough = collide_grains(pair, rough_model, n, g1, g2);
  CollideOptions o;
  o.tangential_velocity = 0.3;
  EXPECT_NEAR(rough.cor_tangential, collide(pair, rough_model, 1.0, o).tangential->cor, 1e-12);
  EXPECT_THROW(collide_grains(pair, rough_model, {-1.0, 0.0, 0.0}, g1, g2), InvalidArgument);
}

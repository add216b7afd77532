// Properties of the static JKR contact (its inverse functions) and of the post-collision
// rules (what an event-driven simulation applies), on random pairs and motions.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "bounce/analysis/rules.hpp"
#include "bounce/contact/jkr.hpp"
#include "property/checks.hpp"
#include "property/generators.hpp"

using namespace bounce;
using namespace bounce::property;

namespace {

constexpr double epsilon = std::numeric_limits<double>::epsilon();

contact::jkr::Parameters jkr_parameters(const Pair& p) {
  return {p.effective_radius(), p.effective_modulus(), *p.surface_energy()};
}

// A contact radius on a stable branch: a = a_fold f, f in [1, 1e3] (a_fold, where the
// inverse's branch starts, is where its derivative vanishes).
rc::Gen<double> radius_above(double a_fold) {
  return rc::gen::map(log_uniform(1.0, 1e3), [a_fold](double f) { return a_fold * f; });
}

using analysis::Vector3;

rc::Gen<Vector3> vector(double scale) {
  return rc::gen::apply([scale](double x, double y, double z) { return Vector3{scale * x, scale * y, scale * z}; },
                        uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-1.0, 1.0));
}

double dot(const Vector3& a, const Vector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vector3& a) { return std::sqrt(dot(a, a)); }

}  // namespace

// JKR, K13 (8) delta(a) = a^2/R - sqrt(2 pi gamma a / E*) and its inverse on the branch
// stable under displacement control (a >= a_sep = a_eq / 36^{1/3}, d delta/da = 0 there):
// contact_radius_from_overlap(overlap(a)) returns a. Tolerances from the conditioning:
// delta is a difference of two terms of size S = a^2/R + sqrt(2 pi gamma a/E*), rounded to a
// few ulps of S, and the root finder brackets a to 2^-49 relative (TOMS 748, eps_tolerance
// 50): the residual |delta(a') - delta| <= 16 eps S, and a' is within that residual over
// |d delta/da| of a, plus the bracket, plus 16 eps a (near the fold, f -> 1, the second bound
// grows without limit and the residual alone is the check).
RC_GTEST_PROP(Jkr, OverlapRoundTripsThroughItsInverse, ()) {
  const Pair pair = *sphere_pair();
  const contact::jkr::Parameters p = jkr_parameters(pair);
  const double a = *radius_above(contact::jkr::separation_contact_radius(p));
  const double delta = contact::jkr::overlap(p, a);
  const double a_back = contact::jkr::contact_radius_from_overlap(p, delta);
  const double adhesive = std::sqrt(2.0 * std::numbers::pi * p.surface_energy * a / p.effective_modulus);
  const double scale = a * a / p.effective_radius + adhesive;
  const double slope = 2.0 * a / p.effective_radius - 0.5 * adhesive / a;  // d delta / da of K13 (8)
  RC_LOG() << "R_eff = " << full(p.effective_radius) << " m, E* = " << full(p.effective_modulus)
           << " Pa, gamma = " << full(p.surface_energy) << " J/m^2, a = " << full(a) << " m\n";
  require_near(contact::jkr::overlap(p, a_back), delta, 16.0 * epsilon * scale, "K13 (8) delta(a(delta)) [m]");
  const double residual_bound = 16.0 * epsilon * scale / std::abs(slope);
  require_near(a_back, a, residual_bound + std::ldexp(a, -49) + 16.0 * epsilon * a, "a(delta(a)) [m]");
}

// JKR, K13 (9) F(a) = 4 E* a^3/(3R) - sqrt(8 pi gamma E* a^3) and its closed-form inverse
// BP04 (8.47) on the branch stable under force control (a >= a_eq / 4^{1/3}, dF/da = 0
// there, F >= F_c = -(3/2) pi gamma R): contact_radius_from_force(force(a)) returns a.
// F is a difference of terms of size S = 4 E* a^3/(3R) + sqrt(8 pi gamma E* a^3), and
// (8.47) takes the square root of 6 pi gamma R F + (3 pi gamma R)^2, which cancels at the
// fold: the residual |F(a') - F| <= 32 eps S (a cube root, a square root and sums of terms
// no larger than S, each a few ulps); a' within it over |dF/da|, plus 32 eps a.
RC_GTEST_PROP(Jkr, ForceRoundTripsThroughItsInverse, ()) {
  const Pair pair = *sphere_pair();
  const contact::jkr::Parameters p = jkr_parameters(pair);
  const double a = *radius_above(contact::jkr::pull_off_contact_radius(p));
  const double force = contact::jkr::force(p, a);
  const double a_back = contact::jkr::contact_radius_from_force(p, force);
  const double elastic = 4.0 * p.effective_modulus * a * a * a / (3.0 * p.effective_radius);
  const double adhesive = std::sqrt(8.0 * std::numbers::pi * p.surface_energy * p.effective_modulus * a * a * a);
  const double scale = elastic + adhesive;
  const double slope = 3.0 * elastic / a - 1.5 * adhesive / a;  // dF/da of K13 (9)
  RC_LOG() << "R_eff = " << full(p.effective_radius) << " m, E* = " << full(p.effective_modulus)
           << " Pa, gamma = " << full(p.surface_energy) << " J/m^2, a = " << full(a) << " m\n";
  RC_ASSERT(force >= contact::jkr::pull_off_force(p) * (1.0 + 16.0 * epsilon));  // K13 after (10)
  require_near(contact::jkr::force(p, a_back), force, 32.0 * epsilon * scale, "K13 (9) F(a(F)) [N]");
  require_near(a_back, a, 32.0 * epsilon * scale / std::abs(slope) + 32.0 * epsilon * a, "a(F(a)) [m]");
}

// The post-collision rule (analysis::apply_restitution, BSHP96 (1)-(3), (8)-(11)) never
// creates energy: for 0 <= e^N <= 1 and -1 <= e^T <= 1 the kinetic energy changes by
// BSHP96 (11), dE = -(1/2) m_eff (1 - (e^N)^2) (g^N)^2 - (1/2) m_eff kappa (1 - (e^T)^2) |g^T|^2
// <= 0; linear momentum and the angular momentum about the contact point are conserved;
// the contact velocity afterwards is -e^N g^N + e^T g^T (BSHP96 (1), (2)). Random unlike
// pairs (or a grain on an elastic or rigid wall, which takes momentum), directions, velocities
// and spins. Tolerances: rounding. The energies are sums of a few products of velocities
// whose updates are rounded to ulps of the largest velocity, so energies agree to ~16 eps of
// the total kinetic energy before and after; momenta to 16 eps of sum m |v| (and R m |v| +
// J |w| for the angular momentum); contact velocities to 16 eps of sum |v| + R |w|.
RC_GTEST_PROP(Rules, PostCollisionRuleNeverCreatesEnergy, ()) {
  const Pair pair = *sphere_or_wall_pair();
  const bool on_wall = pair.body2().is_wall();
  const double cor = *uniform(0.0, 1.0);
  const double cor_tangential = *uniform(-1.0, 1.0);
  const double speed = *valid_speed(pair);
  const Vector3 normal = *vector(1.0);
  RC_PRE(norm(normal) > 1e-3);
  analysis::GrainMotion g1{*vector(speed), *vector(speed / pair.body1().radius)};
  analysis::GrainMotion g2{on_wall ? Vector3{} : *vector(speed), on_wall ? Vector3{} : *vector(speed / pair.body2().radius)};
  // Approaching at the contact: the normal part of v1 - v2 made negative (spins add only
  // tangential parts, BSHP96 (3)).
  const Vector3 n{normal[0] / norm(normal), normal[1] / norm(normal), normal[2] / norm(normal)};
  const double approach = dot({g1.velocity[0] - g2.velocity[0], g1.velocity[1] - g2.velocity[1],
                               g1.velocity[2] - g2.velocity[2]}, n);
  if (approach >= 0.0) {
    const double shift = approach + speed * *uniform(1e-3, 1.0);
    for (int i = 0; i < 3; ++i) g1.velocity[i] -= shift * n[i];
  }
  RC_LOG() << "on_wall = " << on_wall << ", e^N = " << full(cor) << ", e^T = " << full(cor_tangential) << "\n";
  const auto r = analysis::apply_restitution(pair, normal, g1, g2, cor, cor_tangential);

  const double before = analysis::kinetic_energy(pair, g1, g2);
  const double after = analysis::kinetic_energy(pair, r.grain1, r.grain2);
  const double energy_scale = before + after;
  const double m = pair.effective_mass(), kappa = pair.tangential_mass_factor();
  const double gn = r.before.normal_speed, gt = r.before.tangential_speed;
  const double bshp96_11 = -0.5 * m * (1.0 - cor * cor) * gn * gn - 0.5 * m * kappa * (1.0 - cor_tangential * cor_tangential) * gt * gt;
  require_within(r.energy_change, -HUGE_VAL, 16.0 * epsilon * energy_scale, "energy change [J] (never > 0)");
  require_near(r.energy_change, bshp96_11, 16.0 * epsilon * energy_scale, "energy change vs BSHP96 (11) [J]");

  // The contact velocity is a difference of the grains' velocities and surface speeds, each
  // rounded to ulps of its own size: the scale is their sum, not |g| (which can be tiny).
  const auto after_contact = analysis::contact_velocity(pair, normal, r.grain1, r.grain2);
  auto surface_speeds = [&](const analysis::GrainMotion& a, const analysis::GrainMotion& b) {
    return norm(a.velocity) + pair.body1().radius * norm(a.angular_velocity) +
           (on_wall ? 0.0 : norm(b.velocity) + pair.body2().radius * norm(b.angular_velocity));
  };
  const double speed_scale = surface_speeds(g1, g2) + surface_speeds(r.grain1, r.grain2);
  for (int i = 0; i < 3; ++i) {
    require_near(after_contact.normal[i], -cor * r.before.normal[i], 16.0 * epsilon * speed_scale,
                 "g^N after, BSHP96 (1)");
    require_near(after_contact.tangential[i], cor_tangential * r.before.tangential[i], 16.0 * epsilon * speed_scale,
                 "g^T after, BSHP96 (2)");
  }
  if (on_wall) return;
  const Body& b1 = pair.body1();
  const Body& b2 = pair.body2();
  const double m1 = b1.mass(), m2 = b2.mass();
  const double j1 = b1.inertia_factor * m1 * b1.radius * b1.radius;  // BSHP96 (4)
  const double j2 = b2.inertia_factor * m2 * b2.radius * b2.radius;
  // Angular momentum about the contact point: grain 1's centre at +R1 n, grain 2's at -R2 n.
  auto angular = [&](const analysis::GrainMotion& a, const analysis::GrainMotion& b) {
    const Vector3 l1 = cross(Vector3{b1.radius * n[0], b1.radius * n[1], b1.radius * n[2]}, a.velocity);
    const Vector3 l2 = cross(Vector3{-b2.radius * n[0], -b2.radius * n[1], -b2.radius * n[2]}, b.velocity);
    return Vector3{m1 * l1[0] + j1 * a.angular_velocity[0] + m2 * l2[0] + j2 * b.angular_velocity[0],
                   m1 * l1[1] + j1 * a.angular_velocity[1] + m2 * l2[1] + j2 * b.angular_velocity[1],
                   m1 * l1[2] + j1 * a.angular_velocity[2] + m2 * l2[2] + j2 * b.angular_velocity[2]};
  };
  const double momentum_scale = m1 * (norm(g1.velocity) + norm(r.grain1.velocity)) +
                                m2 * (norm(g2.velocity) + norm(r.grain2.velocity));
  const double angular_scale =
      b1.radius * m1 * (norm(g1.velocity) + norm(r.grain1.velocity)) +
      b2.radius * m2 * (norm(g2.velocity) + norm(r.grain2.velocity)) +
      j1 * (norm(g1.angular_velocity) + norm(r.grain1.angular_velocity)) +
      j2 * (norm(g2.angular_velocity) + norm(r.grain2.angular_velocity));
  const Vector3 l_before = angular(g1, g2), l_after = angular(r.grain1, r.grain2);
  for (int i = 0; i < 3; ++i) {
    require_near(m1 * r.grain1.velocity[i] + m2 * r.grain2.velocity[i], m1 * g1.velocity[i] + m2 * g2.velocity[i],
                 16.0 * epsilon * momentum_scale, "linear momentum [kg m/s]");
    require_near(l_after[i], l_before[i], 16.0 * epsilon * angular_scale, "angular momentum about the contact [kg m^2/s]");
  }
}

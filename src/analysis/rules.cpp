#include "bounce/analysis/rules.hpp"

#include <cmath>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::analysis {

namespace {

Vector3 operator+(const Vector3& a, const Vector3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vector3 operator-(const Vector3& a, const Vector3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vector3 operator*(double s, const Vector3& a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(const Vector3& a, const Vector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vector3 unit_normal(const Vector3& n) {
  for (double c : n) require_finite("normal", c);
  const double length = std::sqrt(dot(n, n));
  if (!(length > 0.0)) throw InvalidArgument("normal", "[0, 0, 0]", "a nonzero vector from grain 2 to grain 1");
  return (1.0 / length) * n;
}

void check_motion(const GrainMotion& g, const char* which) {
  for (double c : g.velocity) require_finite(fmt::format("{}.velocity", which), c);
  for (double c : g.angular_velocity) require_finite(fmt::format("{}.angular_velocity", which), c);
}

// J = J_hat m R^2 (BSHP96 (4)); infinite for a wall.
double moment_of_inertia(const Body& b) { return b.inertia_factor * b.mass() * b.radius * b.radius; }

}  // namespace

ContactVelocity contact_velocity(const Pair& pair, const Vector3& normal, const GrainMotion& grain1,
                                 const GrainMotion& grain2) {
  check_motion(grain1, "grain1");
  check_motion(grain2, "grain2");
  const Vector3 n = unit_normal(normal);
  const Body& b1 = pair.body1();
  const Body& b2 = pair.body2();
  // BSHP96 (3); a wall neither moves nor turns.
  Vector3 g = grain1.velocity - b1.radius * cross(grain1.angular_velocity, n);
  if (!b2.is_wall()) g = g - grain2.velocity - b2.radius * cross(grain2.angular_velocity, n);
  ContactVelocity c;
  const double gn = dot(g, n);
  c.normal = gn * n;
  c.tangential = g - c.normal;
  c.normal_speed = std::abs(gn);
  c.tangential_speed = std::sqrt(dot(c.tangential, c.tangential));
  c.approaching = gn < 0.0;
  return c;
}

CollisionRuleResult apply_restitution(const Pair& pair, const Vector3& normal, const GrainMotion& grain1,
                                      const GrainMotion& grain2, double cor, double cor_tangential) {
  require_finite("cor", cor);
  require_finite("cor_tangential", cor_tangential);
  if (cor < 0.0 || cor > 1.0) throw InvalidArgument("cor", fmt::format("{:g}", cor), "0 <= eps^N <= 1 (BSHP96 (1))");
  CollisionRuleResult r;
  r.before = contact_velocity(pair, normal, grain1, grain2);
  if (!r.before.approaching) {
    throw InvalidArgument("normal", "(receding grains)", "grains that approach at the contact: (g . n) < 0");
  }
  const Vector3 n = unit_normal(normal);
  const Body& b1 = pair.body1();
  const Body& b2 = pair.body2();
  const double m = pair.effective_mass(), kappa = pair.tangential_mass_factor();
  // The impulse on grain 1: -(1 + eps^N) m_eff g^N + (eps^T - 1) kappa m_eff g^T.
  const Vector3 impulse = (-(1.0 + cor) * m) * r.before.normal + ((cor_tangential - 1.0) * kappa * m) * r.before.tangential;
  const Vector3 torque_arm = cross(n, impulse);  // n x P
  r.grain1.velocity = grain1.velocity + (1.0 / b1.mass()) * impulse;
  r.grain1.angular_velocity = grain1.angular_velocity - (b1.radius / moment_of_inertia(b1)) * torque_arm;
  if (b2.is_wall()) {
    r.grain2 = grain2;
  } else {
    r.grain2.velocity = grain2.velocity - (1.0 / b2.mass()) * impulse;
    r.grain2.angular_velocity = grain2.angular_velocity - (b2.radius / moment_of_inertia(b2)) * torque_arm;
  }
  r.cor = cor;
  r.cor_tangential = cor_tangential;
  r.energy_change = kinetic_energy(pair, r.grain1, r.grain2) - kinetic_energy(pair, grain1, grain2);
  return r;
}

CollisionRuleResult collide_grains(const Pair& pair, const models::Model& model, const Vector3& normal,
                                   const GrainMotion& grain1, const GrainMotion& grain2,
                                   const CollideOptions& options) {
  const ContactVelocity c = contact_velocity(pair, normal, grain1, grain2);
  if (!c.approaching) {
    throw InvalidArgument("normal", "(receding grains)", "grains that approach at the contact: (g . n) < 0");
  }
  CollideOptions o = options;
  // Without a friction coefficient the grains are smooth: eps^T = 1.
  o.tangential_velocity = model.tangential ? c.tangential_speed : 0.0;
  const dynamics::CollisionOutcome out = collide(pair, model, c.normal_speed, o);
  double cor_tangential = 1.0;  // no tangential motion: nothing to restitute
  if (out.outcome == dynamics::Outcome::stick) {
    cor_tangential = 0.0;  // one body: no relative motion at the contact
  } else if (out.tangential) {
    cor_tangential = out.tangential->cor;
  }
  return apply_restitution(pair, normal, grain1, grain2, out.cor, cor_tangential);
}

double kinetic_energy(const Pair& pair, const GrainMotion& grain1, const GrainMotion& grain2) {
  auto of = [](const Body& b, const GrainMotion& g) {
    if (b.is_wall()) return 0.0;
    return 0.5 * b.mass() * dot(g.velocity, g.velocity) +
           0.5 * moment_of_inertia(b) * dot(g.angular_velocity, g.angular_velocity);
  };
  return of(pair.body1(), grain1) + of(pair.body2(), grain2);
}

}  // namespace bounce::analysis

#pragma once
// Post-collision velocities and spins from the restitution coefficients (BSHP96 §III,
// (1)-(3), (8)-(11), (42)-(43)), for any masses, radii and moments of inertia; what an
// event-driven simulation applies at each collision.
//
// With n the unit vector from grain 2 to grain 1 and g the relative velocity of the
// surfaces at the contact point, BSHP96 (3),
//   g = v1 - v2 - R1 w1 x n - R2 w2 x n,   g^N = (g.n) n,   g^T = g - g^N,
// the impulse on grain 1 (and minus it on grain 2) that gives (g^N)' = -eps^N g^N and
// (g^T)' = eps^T g^T (BSHP96 (1), (2)) is
//   P = -m_eff (1 + eps^N) g^N + m_eff kappa (eps^T - 1) g^T,
//   v1' = v1 + P/m1,  v2' = v2 - P/m2,  w1' = w1 - R1 (n x P)/J1,  w2' = w2 - R2 (n x P)/J2,
// with kappa of BSHP96 (8). Linear momentum and the angular momentum about the contact
// point are conserved, and the kinetic energy changes by BSHP96 (11). (42)-(43) as
// printed carry m_eff/(2 m1) for both parts: that is right for neither (m_eff/m1 for
// the normal part, kappa m_eff/m1 for the tangential); docs/tangential.md.

#include <array>

#include "bounce/analysis/collide.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::analysis {

using Vector3 = std::array<double, 3>;

struct GrainMotion {
  Vector3 velocity{};          ///< [m/s]
  Vector3 angular_velocity{};  ///< [1/s]
};

struct ContactVelocity {
  Vector3 normal{};             ///< g^N [m/s]
  Vector3 tangential{};         ///< g^T [m/s]
  double normal_speed = 0.0;    ///< |g^N|
  double tangential_speed = 0.0;  ///< |g^T|
  bool approaching = false;     ///< g.n < 0: the grains move toward each other
};

/// BSHP96 (3) at the contact; `n` (from grain 2 to grain 1) need not be normalised. A
/// wall (body 2) does not move.
ContactVelocity contact_velocity(const Pair& pair, const Vector3& n, const GrainMotion& grain1,
                                 const GrainMotion& grain2);

struct CollisionRuleResult {
  GrainMotion grain1, grain2;   ///< after the collision
  ContactVelocity before;
  double cor = 0.0;             ///< eps^N used
  double cor_tangential = 0.0;  ///< eps^T used
  double energy_change = 0.0;   ///< kinetic energy after minus before [J]
};

/// Applies given eps^N (0..1) and eps^T (-1..1 in BSHP96; any finite value accepted)
/// to two approaching grains. InvalidArgument if they do not approach.
CollisionRuleResult apply_restitution(const Pair& pair, const Vector3& n, const GrainMotion& grain1,
                                      const GrainMotion& grain2, double cor, double cor_tangential);

/// The same with eps^N(g^N) and eps^T(g^N, g^T) of `model` (its tangential law when
/// g^T > 0 and the model has one, i.e. a friction coefficient; eps^T = 1, smooth grains,
/// otherwise).
/// Sticking grains: eps^N = 0 and, as one body, eps^T = 0 (no relative motion at the
/// contact afterwards).
CollisionRuleResult collide_grains(const Pair& pair, const models::Model& model, const Vector3& n,
                                   const GrainMotion& grain1, const GrainMotion& grain2,
                                   const CollideOptions& options = {});

/// Total kinetic energy, translational and rotational [J] (a wall has none).
double kinetic_energy(const Pair& pair, const GrainMotion& grain1, const GrainMotion& grain2);

}  // namespace bounce::analysis

#pragma once
// Oblique collisions: the tangential motion of BSHP96 §II B driven by the normal
// force of any normal model (the normal motion does not feel the tangential force).
//
//   m_eff kappa zeta'' = F^T,   kappa of BSHP96 (8),   zeta'(0) = g^T      BSHP96 (10)
//
// * asperity law, BSHP96 (27)-(37): F^T = -mu F^N (zeta - zeta_a)/zeta0, the anchor
//   zeta_a reset to zeta whenever |zeta - zeta_a| reaches zeta0 (an asperity breaks
//   and the stored energy is lost). For monotonic zeta this is (35) with its floor;
//   the history form also holds when zeta reverses (docs/decisions.md D11). The Coulomb limit (36)
//   |F^T| <= mu F^N holds by construction.
// * its passive variant: the asperity spring keeps its stored energy E_s, not its
//   extension, when its stiffness k = mu F^N / zeta0 changes: F^T = sqrt(k) u with
//   u' = -sqrt(k) zeta', so E_s = u^2/2 changes only by the work F^T zeta'. The
//   published form keeps the extension, so a stiffening spring gains energy the
//   normal motion never gave (BSHP96's bound -1 <= eps^T then fails; docs/tangential.md).
//   Breaks at the same place, |F^T| = mu F^N.
// * step law, BSHP96 (39) (Haff & Werner, Cundall & Strack):
//   F^T = -min(gamma_s m_eff |g^T|, mu F^N) sgn g^T.
//
// F^N is the total normal force, taken as 0 where it is attractive (asperities carry
// no shear in tension). Where asperities break more than ~1e3 times per time unit
// xi0/g^N, the sawtooth is replaced by its mean, a sliding force mu F^N / 2 (no input
// needs one event per break; docs/tangential.md gives the error).

#include "bounce/dynamics/normal_collision.hpp"
#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/tangential.hpp"
#include "bounce/models/normal_force.hpp"

namespace bounce::dynamics {

/// The tangential motion over a collision whose normal motion is `normal` (its outcome
/// and contact time). F^N(t) comes from the same integration for force-law models and
/// from the trajectory for the dynamic-contact ones.
struct TangentialCollision {
  CollisionOutcome normal;
  TangentialOutcome tangential;
};

/// Normal and tangential motion integrated together (dopri5 in the scaled units of
/// the normal collision; breaks and the switch to and from the averaged sawtooth are
/// events).
TangentialCollision integrate_tangential_collision(const models::NormalForceModel& normal, double effective_mass,
                                                   double normal_speed, double tangential_speed,
                                                   const models::TangentialModel& tangential,
                                                   const NormalCollisionOptions& options = {});

/// The tangential motion driven by a recorded normal force F^N(t) (samples of a
/// finished collision, monotone cubic interpolation between them): for models whose
/// normal motion has its own integrator (krijt, jkr-viscoelastic).
TangentialOutcome integrate_tangential_motion(const std::vector<TrajectorySample>& normal, double effective_mass,
                                              double tangential_speed, const models::TangentialModel& tangential,
                                              const IntegrationSettings& settings = {});

/// Between asperity breaks the published asperity law is linear in the spring's extension
/// p: p'' = -K(tau) p, K = mu (xi0 / zeta0) f / kappa (BSHP96 (10) with (35); tau the scaled
/// time of the normal collision, f its scaled normal force, taken as 0 where attractive).
/// The fundamental solutions y1 (y1(0) = 1, y1'(0) = 0) and y2 (y2(0) = 0, y2'(0) = 1) and K
/// at the scaled times `times` (ascending), integrated with the normal motion to `tolerance`
/// (the eps^T tables of analysis/tables.hpp are built from them).
struct FundamentalSample {
  double y1 = 0.0, dy1 = 0.0, y2 = 0.0, dy2 = 0.0;
  double stiffness = 0.0;  ///< K
};
std::vector<FundamentalSample> fundamental_solutions(const models::NormalForceModel& normal, double effective_mass,
                                                     double normal_speed, const models::TangentialModel& tangential,
                                                     const std::vector<double>& times, double tolerance);

}  // namespace bounce::dynamics

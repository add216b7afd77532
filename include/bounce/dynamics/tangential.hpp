#pragma once
// Oblique collisions: the tangential motion of BSHP96 §II B driven by the normal
// force of any normal model (the normal motion does not feel the tangential force).
//
//   m_eff kappa zeta'' = F^T,   kappa of BSHP96 (8),   zeta'(0) = g^T      BSHP96 (10)
//
// * asperity law, BSHP96 (27)-(37): F^T = -mu F^N (zeta - zeta_a)/zeta0, the anchor
//   zeta_a reset to zeta whenever |zeta - zeta_a| reaches zeta0 (an asperity breaks
//   and the stored energy is lost). For monotonic zeta this is (35) with its floor;
//   the history form also holds when zeta reverses (SPEC §5). The Coulomb limit (36)
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
#include "bounce/models/normal_force.hpp"

namespace bounce::dynamics {

enum class TangentialLaw { asperity, step };
enum class AsperityForm { published, passive };
std::string_view to_string(TangentialLaw law);
std::string_view to_string(AsperityForm form);
TangentialLaw parse_tangential_law(std::string_view text);  ///< "asperity" | "step"
AsperityForm parse_asperity_form(std::string_view text);    ///< "published" | "passive"

struct TangentialModel {
  TangentialLaw law = TangentialLaw::asperity;
  AsperityForm form = AsperityForm::published;
  double friction = 0.0;       ///< mu, BSHP96 (35)-(36)
  double asperity_size = 0.0;  ///< zeta0 [m], BSHP96 (32) (asperity law)
  double shear_damping = 0.0;  ///< gamma_s [1/s], BSHP96 (39) (step law)
  double kappa = 2.0 / 7.0;    ///< BSHP96 (8): 2/7 for homogeneous spheres
  /// Asperity breaks per time unit xi0/g^N above which the sawtooth is averaged (back
  /// below a tenth of it); +inf resolves every break.
  double dense_breaks = 1e3;
};

/// Checks the parameters (mu >= 0; zeta0 > 0 for the asperity law, gamma_s >= 0 for the
/// step law; 0 < kappa <= 1); InvalidArgument names the offending one.
void validate(const TangentialModel& model);

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
                                                   const TangentialModel& tangential,
                                                   const NormalCollisionOptions& options = {});

/// The tangential motion driven by a recorded normal force F^N(t) (samples of a
/// finished collision, monotone cubic interpolation between them): for models whose
/// normal motion has its own integrator (krijt, jkr-viscoelastic).
TangentialOutcome integrate_tangential_motion(const std::vector<TrajectorySample>& normal, double effective_mass,
                                              double tangential_speed, const TangentialModel& tangential,
                                              const IntegrationSettings& settings = {});

}  // namespace bounce::dynamics

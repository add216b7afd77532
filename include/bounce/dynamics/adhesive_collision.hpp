#pragma once
// Head-on collisions of adhesive grains: K13's dynamic model (`krijt`) and its
// instantaneous-crack limit (`jkr-viscoelastic`).

#include "bounce/dynamics/integration.hpp"
#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/adhesive_geometry.hpp"
#include "bounce/models/krijt.hpp"

namespace bounce::dynamics {

/// Where a contact held on its adhesive branch breaks: at the fold (the end K13 (25) assumes for
/// JKR, `contact_end fold`) or at the pull-off point (`contact_end pull-off`, as LAMMPS's pair
/// granular jkr ends it).
using AdhesiveRelease = models::AdhesiveRelease;

struct AdhesiveCollisionOptions {
  /// Relative tolerance (scaled units) of the stiff engine (krijt) and, times 1e-2, of
  /// dopri5 (jkr-viscoelastic). With RODAS, 1e-8 gives COR errors <= 5e-9 for
  /// T_vis 1e-16 to 1e-8 s (docs/benchmarks.md).
  double relative_tolerance = 1e-8;
  long max_steps = 2'000'000;  ///< ~1-5 s of stiff-engine steps: fail fast rather than stall
  bool record_trajectory = false;
  int trajectory_points = 600;       ///< evenly spaced samples over ~2 Hertz contact times (plus every step)
  /// Keep integrating a sticking collision until this time [s] (trajectories of
  /// the settling grains, K13 figs 3 and C2); 0: stop as soon as sticking is certain.
  double follow_time = 0.0;
  /// The contact counts as broken at beta = (1 - break_margin) / k: the crack
  /// speed diverges at 1/k, and the rest of the run-away is instantaneous.
  double break_margin = models::krijt_break_margin;
  StiffEngine engine = StiffEngine::rodas;  ///< krijt only (jkr-viscoelastic is not stiff)
  AdhesiveRelease release = AdhesiveRelease::fold;  ///< the adhesive-branch engine only
};

/// K13: delta, delta', a and the two dissipations integrated by the stiff engine (RODAS,
/// or CVODE's BDF; both with the analytic Jacobian). Ends when beta reaches its upper bound 1/k (the crack runs
/// away: a -> 0 with a' -> -inf in no time; the energy U_E + U_S left then is
/// crack dissipation) or when the mechanical energy U_K + U_E + U_S turns negative
/// (it never increases, so the grains can never separate: stick).
CollisionOutcome integrate_krijt_collision(const models::KrijtParameters& p, double speed,
                                           const AdhesiveCollisionOptions& options = {});

/// Preconditions of both (checked once, by the model registry and analysis::collide):
/// parameters of models::make_model, speed > 0 and finite.
///
/// A contact held on an adhesive equilibrium branch (an instantaneous crack) with the bulk force
/// K13 (19), F_D = 2 A E* a delta': m delta'' = -(F_E(delta) + F_D), a and F_E from the geometry.
/// The pair snaps onto the branch at the geometry's snap overlap and leaves it at its release
/// (options.release); the energies dissipated there are crack_dissipated, the bulk force's
/// bulk_dissipated. Sticking: the mechanical energy below the contact's energy at the release
/// (it never increases). Integrated with dopri5 (not stiff). p gives m*, E*, A (and R, gamma for
/// the scales).
CollisionOutcome integrate_adhesive_collision(const models::AdhesivePair& p, const models::AdhesiveGeometry& geometry,
                                              double speed, const AdhesiveCollisionOptions& options = {});

/// K13's equations with a on the JKR equilibrium (beta = 1): integrate_adhesive_collision on JKR's
/// branch (snap-on at delta = 0, release at delta_c or the pull-off point).
CollisionOutcome integrate_jkr_viscoelastic_collision(const models::AdhesivePair& p, double speed,
                                                      const AdhesiveCollisionOptions& options = {});

}  // namespace bounce::dynamics

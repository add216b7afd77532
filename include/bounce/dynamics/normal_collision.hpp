#pragma once
// Direct integration of a head-on collision under a normal force law
// (BSHP96 (13), BP04 (8.61)): m_eff xi'' = -F(xi, xi'), xi(0) = 0, xi'(0) = g.

#include "bounce/dynamics/integration.hpp"
#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/end_rule.hpp"
#include "bounce/models/normal_force.hpp"

namespace bounce::dynamics {

struct NormalCollisionOptions {
  models::EndRule end_rule = models::EndRule::overlap;
  IntegrationSettings integration;
  bool record_trajectory = false;
  int trajectory_points = 400;  ///< roughly evenly spaced samples over an elastic contact time
};

/// Integrates in the scaled units of BP04 (8.66) (xi0 of (8.65), time xi0/g), so
/// tolerances are dimensionless; events (maximum compression, end of contact) are
/// located on the dense output. The COR is e = -xi'(t_c)/g (BP04 (8.62)).
/// Preconditions (checked once, where the inputs come in: analysis::collide and the model
/// registry): speed and effective_mass > 0 and finite, a validated force law; an adhesive
/// law only with the overlap end rule.
CollisionOutcome integrate_normal_collision(const models::NormalForceModel& model,
                                            double effective_mass, double speed,
                                            const NormalCollisionOptions& options = {});

}  // namespace bounce::dynamics

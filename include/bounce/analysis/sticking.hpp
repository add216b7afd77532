#pragma once
// The sticking velocity: the impact speed below which adhesive grains stick.

#include "bounce/analysis/collide.hpp"

namespace bounce::analysis {

struct StickingVelocity {
  double velocity = 0.0;  ///< the threshold [m/s] (geometric mean of the final bracket)
  double lower = 0.0;     ///< largest speed found to stick
  double upper = 0.0;     ///< smallest speed found to bounce
  int collisions = 0;     ///< collisions computed
  /// The grains stick at every speed up to the transversal sound speed c_t, where the
  /// quasi-static models end (BSHP96 (B11)): no threshold within their validity. A result,
  /// not an error: then velocity = 0 and lower = c_t, upper = 0.
  bool sticks_up_to_sound_speed = false;
};

/// Bracket, then bisect (geometrically) on the outcome until (upper - lower) <=
/// relative_tolerance * upper. For models that cannot stick, InvalidArgument; if
/// the grains stick at every speed up to the transversal sound speed (where the
/// quasi-static models end), sticks_up_to_sound_speed.
/// Assumes a single transition from stick (slow) to bounce (fast), as in every
/// model here without plastic losses; with a yield strength the lowest one is found.
StickingVelocity sticking_velocity(const Pair& pair, const models::Model& model, const CollideOptions& options = {},
                                   double relative_tolerance = 1e-6);

/// BP04 (8.100): the speed where (1/2) m e(g)^2 g^2 = W0, with the exact viscoelastic
/// e(g) (master curve, overlap rule, the model's A) and W0 of (8.95). For models with
/// BP04's scaling (viscoelastic_scales).
double sticking_velocity_bp04(const Pair& pair, const models::Model& model);

}  // namespace bounce::analysis

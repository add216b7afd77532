#pragma once
// The top-level collision API: cor(pair, model, velocity) and friends.

#include <functional>
#include <string>
#include <vector>

#include "bounce/dynamics/integration.hpp"
#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce {

enum class Method {
  automatic,  ///< the master curve where the model has one (and no trajectory is requested)
  integrate,  ///< direct integration
  master,     ///< the master curve (InvalidArgument for models without one)
};
Method parse_method(const std::string& text);  // "integrate" | "master" | "auto"

struct CollideOptions {
  Method method = Method::automatic;
  dynamics::IntegrationSettings integration;
  bool record_trajectory = false;
  int trajectory_points = 400;
};

/// One head-on collision at impact speed `velocity` [m/s]: COR, outcome, contact
/// time, maximum overlap, energy budget, warnings about validity (BSHP96 App. B).
dynamics::CollisionOutcome collide(const Pair& pair, const models::ModelSpec& model, double velocity,
                                   const CollideOptions& options = {});

/// The coefficient of normal restitution alone.
double cor(const Pair& pair, const models::ModelSpec& model, double velocity,
           const CollideOptions& options = {});

/// collide() for each velocity; `progress(done, total)` is called after each one.
std::vector<dynamics::CollisionOutcome> collide_curve(
    const Pair& pair, const models::ModelSpec& model, const std::vector<double>& velocities,
    const CollideOptions& options = {},
    const std::function<void(std::size_t, std::size_t)>& progress = {});

/// Dimensionless characterisation of a viscoelastic collision (BP04 §8.3).
struct ViscoelasticScales {
  double dissipative_constant = 0.0;  ///< A [s]
  double force_constant = 0.0;        ///< C0 [N/m^{3/2}]
  double kappa = 0.0;                 ///< BP04 (8.70)
  double characteristic_velocity = 0.0;  ///< g* (8.88) [m/s]; +inf for A = 0
  double q = 0.0;                     ///< (g/g*)^{1/5} = 2 b kappa
  double reference_overlap = 0.0;     ///< xi0 (8.65) [m]
  double hertz_contact_time = 0.0;    ///< exact elastic contact time [s]
};
ViscoelasticScales viscoelastic_scales(const Pair& pair, const models::ModelSpec& model, double velocity);

}  // namespace bounce

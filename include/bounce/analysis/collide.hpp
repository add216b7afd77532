#pragma once
// The top-level collision API: cor(pair, model, velocity) and friends.

#include <functional>
#include <string>
#include <vector>

#include "bounce/dynamics/integration.hpp"
#include "bounce/dynamics/outcome.hpp"
#include "bounce/dynamics/tangential.hpp"
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
  /// krijt and jkr-viscoelastic: relative tolerance of the contact dynamics (scaled units).
  double adhesive_tolerance = 1e-8;
  /// krijt: the stiff engine (RODAS, or CVODE as an independent cross-check).
  dynamics::StiffEngine stiff_engine = dynamics::StiffEngine::rodas;
  /// g^T [m/s]: > 0 makes the collision oblique; the outcome then has `tangential`
  /// (the model's tangential law, models::tangential_model; docs/tangential.md).
  double tangential_velocity = 0.0;
  /// krijt and jkr-viscoelastic: keep integrating a sticking collision until this
  /// time [s] (to record how the grains settle); 0 stops when sticking is certain.
  double follow_time = 0.0;
};

/// Sticking grains merge (BP04 §8.3.4, SPEC §4.1): one body of mass m1 + m2 moving,
/// by momentum conservation, with m1 g / (m1 + m2) along the line of centres in the
/// frame where body 2 rests before the impact (m_eff g / m2). A wall keeps the grain
/// (infinite mass, velocity 0).
struct MergedBody {
  double mass = 0.0;      ///< [kg]; +inf with a wall
  double velocity = 0.0;  ///< [m/s], frame of body 2 before the impact
};
MergedBody merged_body(const Pair& pair, double velocity);

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

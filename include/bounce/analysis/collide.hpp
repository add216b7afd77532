#pragma once
// One collision of a configured model (models::Model): cor(pair, model, velocity) and the
// full outcome. The model's physics picks the engine (a force law: the normal engine or
// the master curve; K13's dynamic contact: its own engines); the analysis adds what every
// model shares: plastic losses, the tangential motion of oblique collisions, warnings.

#include <functional>
#include <string_view>
#include <vector>

#include "bounce/core/parameters.hpp"
#include "bounce/dynamics/integration.hpp"
#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/model.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::analysis {

enum class Method {
  automatic,  ///< the master curve where the model has one (and no trajectory is requested)
  integrate,  ///< direct integration
  master,     ///< the master curve (InvalidArgument for models without one)
};
Method parse_method(std::string_view text);  ///< "auto" | "integrate" | "master"

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
  /// (the model's tangential law; docs/tangential.md).
  double tangential_velocity = 0.0;
  /// krijt and jkr-viscoelastic: keep integrating a sticking collision until this
  /// time [s] (to record how the grains settle); 0 stops when sticking is certain.
  double follow_time = 0.0;
};

/// The options a model's numerical parameters set (method, tolerance, adhesive_tolerance,
/// stiff_engine; parameters bound by models::bind_model_parameters).
CollideOptions collide_options(const Parameters& model_parameters);

/// Sticking grains merge (BP04 §8.3.4): one body of mass m1 + m2 moving, by momentum
/// conservation, with m1 g / (m1 + m2) along the line of centres in the frame where body 2
/// rests before the impact. A wall keeps the grain (infinite mass, velocity 0).
struct MergedBody {
  double mass = 0.0;      ///< [kg]; +inf with a wall
  double velocity = 0.0;  ///< [m/s], frame of body 2 before the impact
};
MergedBody merged_body(const Pair& pair, double velocity);

/// InvalidArgument("velocity") unless 0 < g <= the transversal sound speed c_t (BSHP96
/// (B11): the quasi-static models end there) and (1/2) m_eff g^2 is a normal double.
void require_impact_velocity(const Pair& pair, double velocity);

/// One head-on (or, with a tangential velocity, oblique) collision at impact speed
/// `velocity` [m/s]: COR, outcome, contact time, maximum overlap, energy budget, warnings
/// about validity (BSHP96 App. B). InvalidArgument for a speed require_impact_velocity refuses.
dynamics::CollisionOutcome collide(const Pair& pair, const models::Model& model, double velocity,
                                   const CollideOptions& options = {});

/// The coefficient of normal restitution alone.
double cor(const Pair& pair, const models::Model& model, double velocity, const CollideOptions& options = {});

/// Dimensionless characterisation of a Hertz-type collision (BP04 §8.3).
struct ViscoelasticScales {
  double dissipative_constant = 0.0;     ///< A [s]
  double force_constant = 0.0;           ///< C0 [N/m^{3/2}]
  double kappa = 0.0;                    ///< BP04 (8.70)
  double characteristic_velocity = 0.0;  ///< g* (8.88) [m/s]; +inf for A = 0
  double q = 0.0;                        ///< (g/g*)^{1/5} = 2 b kappa
  double reference_overlap = 0.0;        ///< xi0 (8.65) [m]
  double hertz_contact_time = 0.0;       ///< exact elastic contact time [s]
};
/// InvalidArgument("model", …) for a model without BP04's scaling (power-law, krijt, jkr-viscoelastic).
ViscoelasticScales viscoelastic_scales(const Pair& pair, const models::Model& model, double velocity);

}  // namespace bounce::analysis

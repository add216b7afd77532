#pragma once
// Collision models by keyword (SPEC §7 `--model`).
//
// Registry: one keyword <-> one row of collision_models() <-> one force class.
// To add a model: implement models::NormalForceModel (normal_force.hpp), add a
// row below (src/models/registry.cpp) and a branch in make_normal_force.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bounce/contact/convex.hpp"
#include "bounce/models/end_rule.hpp"
#include "bounce/models/krijt.hpp"
#include "bounce/models/normal_force.hpp"
#include "bounce/models/tangential.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::models {

/// Everything that selects and parametrises a collision model (SI units).
struct ModelSpec {
  std::string name = "viscoelastic";
  std::optional<double> dissipative_constant;  ///< A [s] (BP04 (8.38)); or from the viscosities
  std::optional<double> shear_viscosity;       ///< eta1 [Pa s] (BSHP96 (17))
  std::optional<double> bulk_viscosity;        ///< eta2 [Pa s] (BSHP96 (17))
  models::EndRule end_rule = models::EndRule::overlap;
  std::optional<convex::Curvatures> curvatures;  ///< general convex bodies: C0 of (8.21) replaces rho
  std::optional<PowerLawParameters> power_law;   ///< the `power-law` model
  // Adhesive models (docs/adhesive.md).
  std::optional<double> relaxation_time;  ///< T_vis [s] (krijt, jkr-viscoelastic; A = T_vis/nu^2 unless A given)
  double z0 = 0.2e-9;                     ///< equilibrium separation [m]; sigma0 = gamma/z0 (krijt)
  double k = 0.02;                        ///< relaxed / instantaneous modulus (krijt), 0 < k < 1
  std::optional<double> dissipative_constant_b;  ///< B [s] of BP04 (8.57) (adhesive-viscoelastic)
  std::optional<double> yield_strength;   ///< Y [Pa]: adds Thornton-Ning plastic losses, K13 (28)-(30)
  // Oblique collisions (docs/tangential.md): the tangential force law.
  models::TangentialLaw tangential_law = models::TangentialLaw::asperity;
  models::AsperityForm asperity_form = models::AsperityForm::published;
  std::optional<double> friction;        ///< mu, BSHP96 (35)-(36)
  std::optional<double> asperity_size;   ///< zeta0 [m], BSHP96 (32)
  std::optional<double> shear_damping;   ///< gamma_s [1/s], BSHP96 (39)
};

struct ModelInfo {
  std::string name;
  std::string summary;
  std::string references;
  bool has_master_curve;
  bool adhesive;         ///< needs gamma; outcome can be "stick"
  bool dynamic_contact;  ///< contact radius dynamics of K13 (krijt, jkr-viscoelastic)
};
const std::vector<ModelInfo>& collision_models();
/// InvalidArgument("model", name, "one of …") for an unknown keyword.
const ModelInfo& model_info(const std::string& name);

/// BP04 (8.38): A = (1/3) (3 eta2 - eta1)^2 / (3 eta2 + 2 eta1) (1 - nu^2)(1 - 2 nu) / (E nu^2).
double dissipative_constant_from_viscosities(double shear_viscosity, double bulk_viscosity,
                                             double youngs_modulus, double poisson_ratio);

/// A for this pair: given, from eta1, eta2 (like materials only, BP04 (8.38)), or
/// T_vis / nu^2 (K13 after (18)); 0 for `hertz`.
double dissipative_constant(const ModelSpec& spec, const Pair& pair);
/// B of BP04 (8.57): given, from eta1, eta2 ((8.58) as corrected in SPEC §4.1), or A.
double dissipative_constant_b(const ModelSpec& spec, const Pair& pair, double a);
/// C0, the equivalent radius (a^2 = R xi) and m_eff: spheres, walls or convex bodies.
HertzGeometry hertz_geometry(const ModelSpec& spec, const Pair& pair);
/// The force law of `spec` for `pair` (validates every parameter); not for the
/// dynamic-contact models (krijt, jkr-viscoelastic), see krijt_parameters.
std::unique_ptr<NormalForceModel> make_normal_force(const ModelSpec& spec, const Pair& pair);

/// The tangential force law of `spec` for `pair` (kappa of BSHP96 (8) from the pair's
/// moments of inertia), validated: the asperity law needs mu and zeta0, the step law
/// mu and gamma_s (InvalidArgument names the missing or bad one).
TangentialModel tangential_model(const ModelSpec& spec, const Pair& pair);

/// Parameters of K13's model for this pair: gamma of the pair, T_vis, A (given or
/// T_vis/nu^2), z0 and k, all validated. `jkr-viscoelastic` needs only A (or T_vis).
KrijtParameters krijt_parameters(const ModelSpec& spec, const Pair& pair);

}  // namespace bounce::models

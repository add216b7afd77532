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
#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/normal_force.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::models {

/// Everything that selects and parametrises a collision model (SI units).
struct ModelSpec {
  std::string name = "viscoelastic";
  std::optional<double> dissipative_constant;  ///< A [s] (BP04 (8.38)); or from the viscosities
  std::optional<double> shear_viscosity;       ///< eta1 [Pa s] (BSHP96 (17))
  std::optional<double> bulk_viscosity;        ///< eta2 [Pa s] (BSHP96 (17))
  dynamics::EndRule end_rule = dynamics::EndRule::overlap;
  std::optional<convex::Curvatures> curvatures;  ///< general convex bodies: C0 of (8.21) replaces rho
  std::optional<PowerLawParameters> power_law;   ///< the `power-law` model
};

struct ModelInfo {
  std::string name;
  std::string summary;
  std::string references;
  bool has_master_curve;
};
const std::vector<ModelInfo>& collision_models();
/// InvalidArgument("model", name, "one of …") for an unknown keyword.
const ModelInfo& model_info(const std::string& name);

/// BP04 (8.38): A = (1/3) (3 eta2 - eta1)^2 / (3 eta2 + 2 eta1) (1 - nu^2)(1 - 2 nu) / (E nu^2).
double dissipative_constant_from_viscosities(double shear_viscosity, double bulk_viscosity,
                                             double youngs_modulus, double poisson_ratio);

/// A for this pair: given, or from eta1, eta2 (like materials only); 0 for `hertz`.
double dissipative_constant(const ModelSpec& spec, const Pair& pair);
/// C0, the equivalent radius (a^2 = R xi) and m_eff: spheres, walls or convex bodies.
HertzGeometry hertz_geometry(const ModelSpec& spec, const Pair& pair);
/// The force law of `spec` for `pair` (validates every parameter).
std::unique_ptr<NormalForceModel> make_normal_force(const ModelSpec& spec, const Pair& pair);

}  // namespace bounce::models

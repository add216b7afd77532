#pragma once
// A collision model configured for one pair: what a registry row's factory makes from
// validated parameters (registry.hpp), and all that the engines (dynamics) and the analysis
// need from it. Physics only: no engine, no output format.

#include <memory>
#include <optional>
#include <string>

#include "bounce/models/end_rule.hpp"
#include "bounce/models/krijt.hpp"
#include "bounce/models/normal_force.hpp"
#include "bounce/models/tangential.hpp"

namespace bounce::models {

/// What a model can do; the registry derives from it which shared parameters the model
/// takes (registry.hpp) and the analysis which methods and checks apply.
struct Capabilities {
  bool adhesive = false;         ///< needs gamma; the outcome can be "stick"
  bool dynamic_contact = false;  ///< the contact radius is integrated (K13), not a function of the overlap
  bool master_curve = false;     ///< the viscoelastic master curves e(kappa) apply (method=master)
  bool stiff = false;            ///< integrated by the stiff engine (stiff_engine = rodas | cvode)
  bool convex = false;           ///< general convex bodies (curvature radii) change its force constant
};

/// K13's dynamic contact: contact radius a and approach delta integrated together.
struct DynamicContact {
  KrijtParameters parameters;
  /// a held on the JKR equilibrium (jkr-viscoelastic, the fast-crack limit) instead of
  /// following K13's crack law (krijt).
  bool instantaneous_crack = false;
};

/// What a model assumes about adhesion: which validity warnings and closed forms apply.
enum class Adhesion {
  unchecked,   ///< no Hertz geometry to compare with (power-law)
  negligible,  ///< left out; BP04 (8.99) says when that holds
  weak,        ///< BP04's quasi-static estimate, (8.56)-(8.58) with (8.95)-(8.101)
  modelled,    ///< JKR contact dynamics (K13)
};

/// The constants of BP04's dimensional analysis for a Hertz-type force (§8.3): kappa (8.70),
/// g* (8.88), xi0 (8.65) and the master curves follow from them.
struct HertzScaling {
  double force_constant = 0.0;        ///< C0 [N/m^{3/2}] (rho for spheres, BP04 (8.21) for convex bodies)
  double dissipative_constant = 0.0;  ///< A [s]
};

struct Model {
  std::string name;           ///< the registry keyword
  Capabilities capabilities;  ///< as the row declares them

  // The normal interaction: a force law (most models) or K13's dynamic contact.
  std::shared_ptr<const NormalForceModel> force;
  std::optional<DynamicContact> dynamic_contact;

  // The slots every model has (the registry fills them from the shared parameters).
  EndRule end_rule = EndRule::overlap;
  std::optional<double> yield_strength;  ///< Y [Pa]: Thornton-Ning losses, K13 (28)-(30)
  std::optional<TangentialModel> tangential;  ///< with a friction coefficient: oblique collisions

  // What the analysis reports and checks.
  std::optional<HertzScaling> hertz;           ///< Hertz-type forces: kappa, g*, master curves
  std::optional<double> dissipative_constant;  ///< A [s], where the model has one
  double viscous_time = 0.0;   ///< viscous relaxation time, for BSHP96 (B12) / BP04 (8.26)
  double z0 = 0.2e-9;          ///< equilibrium separation [m] of the Tabor parameter K13 (11)
  Adhesion adhesion = Adhesion::negligible;
};

}  // namespace bounce::models

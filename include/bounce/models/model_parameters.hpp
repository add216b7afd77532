#pragma once
// Each model's own parameters as a struct (its registry row's field table, registry.cpp, declares
// them once: name, unit, range, default, help; the front door binds and checks the values and
// hands the struct to the model's factory), and what every factory gets beside them.

#include <optional>

#include "bounce/contact/convex.hpp"
#include "bounce/models/end_rule.hpp"
#include "bounce/models/normal_force.hpp"

namespace bounce::models {

/// What a factory gets beside its model's own parameters, from the parameters every model
/// shares (make_model reads them once).
struct ModelContext {
  /// The bodies' curvatures, for a model whose traits take convex bodies, where given.
  std::optional<contact::convex::Curvatures> shape;
  /// The end rule, one the model declares (a contact held on its branch ends by it).
  EndRule end_rule = EndRule::overlap;
};

/// viscoelastic, viscoelastic-shifted: the dissipative constant A given, from the viscosities
/// eta1 and eta2 (BP04 (8.38)), or from T_vis (K13 after (18)); exactly one of the three.
struct ViscousParameters {
  std::optional<double> dissipative_constant;  ///< A [s]
  std::optional<double> shear_viscosity;       ///< eta1 [Pa s]
  std::optional<double> bulk_viscosity;        ///< eta2 [Pa s]
  std::optional<double> relaxation_time;       ///< T_vis [s]
};

/// adhesive-viscoelastic: the same, BP04 (8.57)'s B and z0 (the Tabor parameter's).
struct AdhesiveViscousParameters : ViscousParameters {
  std::optional<double> dissipative_constant_b;  ///< B [s] (default: from eta1 and eta2, else A)
  double z0 = 0.0;                               ///< equilibrium separation [m]
};

/// jkr-viscoelastic, maugis-viscoelastic: the bulk damping of K13 (19) (A given, or T_vis / nu^2,
/// K13 after (18)) and z0 (the Tabor parameter's; Maugis' lambda).
struct ContactModelParameters {
  std::optional<double> relaxation_time;       ///< T_vis [s]
  std::optional<double> dissipative_constant;  ///< A [s]
  double z0 = 0.0;                             ///< equilibrium separation [m]
};

/// krijt: the same (T_vis required: its crack law's) and the crack law's k.
struct CrackModelParameters : ContactModelParameters {
  double k = 0.0;  ///< relaxed / instantaneous modulus of K13 (16)-(17)
};

// power-law: PowerLawParameters (normal_force.hpp), BP04 (8.63).

}  // namespace bounce::models

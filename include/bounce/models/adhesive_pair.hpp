#pragma once
// An adhesive pair's parameters as the contact models take them (jkr-viscoelastic,
// maugis-viscoelastic, krijt): the pair, its work of adhesion, the bulk damping of K13 (19) and
// the equilibrium separation of the surface forces. No model's own parameters: krijt's crack law
// adds T_vis and k (KrijtParameters, krijt.hpp).

namespace bounce::models {

struct AdhesivePair {
  double effective_radius = 0.0;      ///< R [m]
  double effective_modulus = 0.0;     ///< E* [Pa]
  double effective_mass = 0.0;        ///< m* [kg]
  double surface_energy = 0.0;        ///< gamma [J/m^2], the work of adhesion
  double dissipative_constant = 0.0;  ///< A [s] of K13 (19)
  double z0 = 0.2e-9;                 ///< equilibrium separation [m]; sigma0 = gamma / z0
};

}  // namespace bounce::models

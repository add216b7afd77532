#pragma once
// Private: the model parameters, each declared once (name, unit, range, default, help),
// for the registry's rows (registry.cpp) and the factories that read them.

#include "bounce/core/parameters.hpp"

namespace bounce::models::catalogue {

// Dissipation of the Hertz-type laws.
ParameterSpec dissipative_constant();  ///< A [s]
ParameterSpec shear_viscosity();       ///< eta1 [Pa s]
ParameterSpec bulk_viscosity();        ///< eta2 [Pa s]
ParameterSpec relaxation_time();       ///< tvis [s]
ParameterSpec dissipative_constant_b();  ///< B [s] of BP04 (8.57)
// Adhesion (K13's crack law and the Tabor parameter).
ParameterSpec z0();  ///< equilibrium separation [m]
ParameterSpec krijt_z0();  ///< the same, over the range krijt's crack law is tested on
ParameterSpec k();   ///< relaxed / instantaneous modulus
// BP04 (8.63).
ParameterSpec power_d1();
ParameterSpec power_alpha();
ParameterSpec power_d2();
ParameterSpec power_beta();
ParameterSpec power_gamma();

}  // namespace bounce::models::catalogue

#pragma once
// Private: the model parameters, each declared once (name, unit, range, default, help),
// for the registry's rows (registry.cpp) and the factories that read them.

#include "bounce/core/fields.hpp"
#include "bounce/core/parameters.hpp"
#include "bounce/models/model_parameters.hpp"

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

// Each model's parameter struct (model_parameters.hpp) and its field table, in the order
// --help, the docs and Python list them.
struct NoParameters {};  ///< hertz
const FieldTable<NoParameters>& no_fields();
const FieldTable<ViscousParameters>& viscous_fields();                   ///< A, eta1, eta2, tvis
const FieldTable<PowerLawParameters>& power_law_fields();                ///< D1, alpha, D2, beta, gamma
const FieldTable<AdhesiveViscousParameters>& adhesive_viscous_fields();  ///< the viscous ones, B, z0
const FieldTable<ContactModelParameters>& contact_fields();              ///< tvis, A, z0
const FieldTable<CrackModelParameters>& crack_fields();                  ///< tvis, A, z0 (krijt's range), k

}  // namespace bounce::models::catalogue

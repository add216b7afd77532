#pragma once
// How an adhesive (JKR) contact of two spheres resists rolling, sliding and twisting, and the
// energy that breaks it: Dominik & Tielens's model (DT95, DT97) in the form Wada et al. 2007
// (W07 §2.2) use (docs/resistance.md). These papers write gamma_s for the energy of ONE
// surface; bounce's gamma is the work of adhesion, 2 gamma_s for like surfaces, so every
// formula here takes gamma_s = gamma / 2.

#include <string>

#include "bounce/pair/pair.hpp"

namespace bounce::contact::resistance {

/// W07's standard critical rolling displacement, 8 Å [m] (DT95's lower bound is 2 Å; Heim et
/// al. 1999 measured 3.2 nm on SiO2 spheres).
inline constexpr double standard_critical_rolling = 8e-10;

/// One mode of motion: a spring up to its critical displacement, beyond which the contact
/// moves inelastically against a constant limit.
struct Mode {
  double stiffness = 0.0;              ///< [N/m] (rolling: on xi; sliding) or [N m/rad] (twisting)
  double critical_displacement = 0.0;  ///< [m] (rolling xi_crit, sliding xi_s) or [rad] (twisting)
  double limit = 0.0;                  ///< limiting moment [N m] (rolling, twisting) or force [N] (sliding)
  double energy = 0.0;                 ///< the limit's work over a quarter turn [J] (E_roll, E_slide, E_twist)
};

/// Everything bounce prints for a contact (`bounce contact resistance`).
struct Resistance {
  double surface_energy = 0.0;    ///< gamma_s = gamma/2, the literature's gamma [J/m^2]
  double contact_radius = 0.0;    ///< a0, at zero load [m]
  double pull_off_force = 0.0;    ///< F_c = 3 pi gamma_s R, a magnitude [N]
  double critical_overlap = 0.0;  ///< delta_c: the contact breaks at overlap -delta_c [m]
  double break_energy = 0.0;      ///< E_break, from equilibrium to the break [J]
  double rolling_force = 0.0;     ///< F_roll = 6 pi gamma_s xi_crit = M_roll / (2R) [N]
  Mode rolling, sliding, twisting;
};

/// What the resistance takes of a pair of materials, whatever the radii (a DEM computes it once per
/// pair of materials, then each contact's Resistance from its R_eff).
struct Materials {
  double effective_modulus = 0.0;   ///< E* [Pa]
  double surface_energy = 0.0;      ///< gamma, the work of adhesion [J/m^2]
  double tangential_modulus = 0.0;  ///< Mindlin's G*: 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2 [Pa]
  double series_shear = 0.0;        ///< 2 G1 G2 / (G1 + G2), the twisting spring's [Pa]
  double weaker_shear = 0.0;        ///< min(G1, G2), the sliding and twisting limits' [Pa]
};

/// The pair's Materials; InvalidArgument naming "gamma", and `who` as what needs it, where a
/// material has no work of adhesion.
Materials materials_of(const Pair& pair, const std::string& who = "contact resistance");

/// The contact of `pair` (spheres or a sphere on a wall; both materials with a work of adhesion)
/// with critical rolling displacement `xi_crit` [m], 0 < xi_crit < a0. Throws InvalidArgument
/// naming "xi_crit" or "gamma" otherwise.
Resistance contact_resistance(const Pair& pair, double xi_crit);

/// The same for a contact of effective radius R [m] (R1 against a wall) between `materials`,
/// unchecked (its caller checks xi_crit < a0).
Resistance contact_resistance(const Materials& materials, double effective_radius, double xi_crit);

/// What a DEM step needs of a contact of effective radius R (one cube root): W07 §2.2's springs.
struct Springs {
  double contact_radius = 0.0;     ///< a0 [m]
  double rolling = 0.0;            ///< k_r [N/m]
  double sliding = 0.0;            ///< k_s [N/m]
  double sliding_critical = 0.0;   ///< xi_s [m]
  double twisting = 0.0;           ///< k_t [N m/rad]
  double twisting_critical = 0.0;  ///< phi_crit [rad]
};
Springs springs(const Materials& materials, double effective_radius);

/// E_break / (F_c delta_c) = 1.5426…: the work from equilibrium (a = a0) to the fold
/// (a = a0/6^{2/3}, delta = -delta_c) on W07's JKR curve, in closed form.
double break_energy_factor();

}  // namespace bounce::contact::resistance

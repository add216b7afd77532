#pragma once
/* Is a DEM time step (LAMMPS's velocity Verlet) short enough for a contact? (docs/lammps.md, Time step.)

   Velocity Verlet integrates a contact explicitly: linearised about its state, its force is
   F = k xi + D xi' with the law's own stiffness k = dF_E/dxi (the elastic part, at rate 0) and
   damping D = dF/dxi'. With the rate taken at the half step (`integration plain`, LAMMPS's own
   pair styles) the step is stable while (k dt^2/m_eff)/4 + (1/2) D dt/m_eff < 1 (for k = 0:
   dt < 2 m_eff/D); with the rate predicted by the last force (`corrected`) while
   (k dt^2/m_eff)/4 + D dt/m_eff < 1; a crack law's rate (krijt, corrected) is implicit and only
   the first term counts. (Jury's conditions on the step's amplification polynomial; for plain:
   z^2 + (a + b - 2) z + 1 - b, a = k dt^2/m_eff, b = D dt/m_eff.) The sum is the contact's
   `stability`: 1 or more cannot be integrated (the energy grows each step), and above
   `coarse_stability` the step is a tenth of that limit or more: a period 2 pi sqrt(m_eff/k) under
   10 steps, or a damping time m_eff/D under 10 steps (plain: 5), which follows the law badly.

   A contact is checked where its overlap first exceeds `recheck` times the overlap it was last
   checked at (its history keeps that overlap): k and D of bounce's laws grow with the overlap, as
   sqrt(xi) for Hertz's, so the check sees each contact near its deepest overlap, within
   sqrt(1.2) = 1.1 in k and D, at a few force evaluations some 20-40 times per collision. */

#include <string>

#include "bounce/models/dem_law.hpp"

namespace bounce::dem {

/// A contact is reported (a WARNING once per run) above this stability, and stops LAMMPS (an
/// ERROR) at 1.
constexpr double coarse_stability = 0.1;
/// Checked again where the overlap exceeds this times the overlap of the last check.
constexpr double recheck = 1.2;

struct StepCheck {
  double stiffness = 0.0;  ///< k = dF_E/dxi (<= 0 counts as 0) [N/m]
  double damping = 0.0;    ///< D = dF/dxi' [kg/s]
  double stability = 0.0;  ///< (k dt^2/m_eff)/4 + q D dt/m_eff (q = 1/2 plain, 1 corrected, 0 implicit)
  double elastic_term = 0.0;  ///< its first term
  double weight = 0.0;        ///< q
  double effective_mass = 0.0;  ///< [kg]
  /// The largest dt with stability 1 [s] (where stability > 0).
  double largest_step(double dt) const;
  /// The numbers, for a message: k, D, m_eff, the period and damping time in steps, the stability.
  std::string describe(double dt) const;
};

/// Whether a contact at `overlap` is due for a check, given the overlap of its last check (0:
/// none); where it is, that overlap becomes `overlap`.
bool check_due(double overlap, double& checked);

/// The check of a law's contact at overlap xi > 0 and rate xi' (q: the rate's weight above).
StepCheck check_step(const models::DemLaw& law, const models::ContactGeometry& g, double overlap, double rate,
                     double dt, double q);

/// The check of a crack law's contact (krijt) of state s, whose force there is F_E + D xi'.
StepCheck check_crack_step(const models::DemCrackLaw& law, const models::ContactGeometry& g, double overlap,
                           const models::CrackState& s, const models::DemCrackLaw::Force& force, double dt, double q);

}  // namespace bounce::dem


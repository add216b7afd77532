/* One contact over one LAMMPS step: what pair_style bounce (atom-atom) and fix wall/bounce
   (atom-wall) both do with a bounce contact law (docs/lammps.md, What happens in a contact). */

#ifndef BOUNCE_LAMMPS_CONTACT_STEP_H
#define BOUNCE_LAMMPS_CONTACT_STEP_H

#include "bounce/models/contact_law.hpp"
#include "step_check.h"

namespace bounce::lammps {

// Per contact: the tangential spring (models::tangential_step), the last normal force, the overlap
// at which the step was last checked (step_check.h); for a crack law (krijt), then its state
// (models::CrackState, 4 values), the force its forming step lent, the last bulk force and
// overlap rate, and the energy stored at the last step (for the energies it dissipates). A pair
// style whose laws have no crack keeps the first history_size values only.
constexpr int history_size = 5;
constexpr int crack_history_size = 13;
constexpr int last_force = 3;
constexpr int checked_overlap = 4;
constexpr int crack_state = 5;
constexpr int lent_force = 9;
constexpr int last_bulk_force = 10;
constexpr int last_rate = 11;
constexpr int last_stored = 12;

/// The contact's geometry and motion this step; n points from body 2 (atom j, the wall) to
/// body 1 (atom i).
struct Kinematics {
  double n[3];
  double overlap;     ///< R_i + R_j - r (R_i - distance for a wall) [m]
  double vn;          ///< (v_i - v_j) . n, the half-step value LAMMPS has [m/s]
  double sliding[3];  ///< the contact points' relative velocity in the tangent plane [m/s]
};

struct StepSettings {
  double dt;
  bool update_history;  ///< false in LAMMPS's setup
  bool corrected;       ///< integration corrected (and not in setup)
};

struct ContactForce {
  double normal = 0.0;                       ///< along n, positive: repulsive [N]
  double tangential[3] = {0.0, 0.0, 0.0};    ///< at the contact point [N]
  /// The explicit step's check at this contact, where it was due (step_check.h).
  StepCheck check;
  // A crack law's energies (0 for the others) [J]: released by the crack and by the bulk force in
  // this step (0 in LAMMPS's setup), and stored in the contact at its end.
  double crack_dissipated = 0.0;
  double bulk_dissipated = 0.0;
  double elastic = 0.0;
  double surface = 0.0;
  bool finite() const;
};

/// The force of a contact that exists (overlap > the law's snap overlap, 0 but for a contact that
/// forms before touching, or touching and overlap > release, with
/// release = law.normal->release_overlap(g)) or has just ended inside this step (touching and
/// not beyond release; with `corrected` it then still gets its impulse's correction). Updates
/// `touch` and the history (cleared when the contact ends). A crack law (law.crack) ends its
/// contact itself, and ignores `release`.
ContactForce contact_step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                          double release, const StepSettings& s, int& touch, double* history);

}  // namespace bounce::lammps

#endif

#pragma once
// What a DEM contact's step takes and gives (docs/architecture.md, The DEM layer): the two bodies'
// motion, the contact's kinematics, the step's settings, the contact's force and the loads it puts
// on both bodies.

#include "bounce/dem/step_check.hpp"
#include "bounce/models/contact_law.hpp"

namespace bounce::dem {

/// A body's motion where a contact needs it.
struct Motion {
  const double* x;      ///< centre [m]
  const double* v;      ///< velocity [m/s] (LAMMPS's: at the half step)
  const double* omega;  ///< angular velocity [rad/s]
  double radius;        ///< [m]
};

/// The contact's geometry and motion this step; n points from body 2 (atom j, the wall) to
/// body 1 (atom i).
struct Kinematics {
  double n[3];
  double overlap;     ///< R_i + R_j - r (R_i - distance for a wall) [m]
  double vn;          ///< (v_i - v_j) . n [m/s]
  double sliding[3];  ///< the contact points' relative velocity in the tangent plane [m/s]
};

/// Two spheres at distance r > 0 (as pair granular takes them; the lever arm is the radius).
Kinematics pair_kinematics(const Motion& i, const Motion& j, double r);
/// A sphere and a flat wall whose normal into the box is `sign` (+1 or -1) along `axis`.
Kinematics wall_kinematics(const Motion& i, int axis, double sign, double overlap);

struct StepSettings {
  double dt;
  bool update_history;  ///< false in LAMMPS's setup (the forces at the run's start)
  bool corrected;       ///< integration corrected (and not in setup)
};

struct ContactForce {
  double normal = 0.0;                     ///< along n, positive: repulsive [N]
  double tangential[3] = {0.0, 0.0, 0.0};  ///< at the contact point [N]
  /// The explicit step's check at this contact, where it was due (step_check.hpp).
  StepCheck check;
  // A crack law's energies (0 for the others) [J]: released by the crack and by the bulk force in
  // this step (0 in LAMMPS's setup), and stored in the contact at its end.
  double crack_dissipated = 0.0;
  double bulk_dissipated = 0.0;
  double elastic = 0.0;
  double surface = 0.0;
  bool finite() const;
};

/// What a sub-model beyond the normal law is given: the contact, and the normal law's force at
/// this step and the last (the force now for a contact that forms in this step).
struct SubContext {
  const models::DemModel& law;
  const models::ContactGeometry& g;
  const Kinematics& k;
  const StepSettings& s;
  double normal_force;           ///< [N], positive: repulsive
  double previous_normal_force;  ///< [N]
};

/// Whether a pair at `overlap` that is not in contact is within reach of forming one (the law's
/// snap overlap: 0 but for a contact that forms before touching).
inline bool within_reach(const models::DemModel& law, const models::ContactGeometry& g, double overlap) {
  return overlap > law.snap_overlap(g);
}

/// The force on body 1 (body 2 takes -force) and the torques on both, the lever arm being each
/// radius (as in BSHP96's (10)).
struct Loads {
  double force[3];
  double torque1[3];
  double torque2[3];
};
Loads loads(const ContactForce& c, const Kinematics& k, double radius1, double radius2);

}  // namespace bounce::dem

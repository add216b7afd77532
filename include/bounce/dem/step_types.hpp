#pragma once
// What a DEM contact's step takes and gives (docs/architecture.md, The DEM layer): the two bodies'
// motion, the contact's kinematics, the step's settings, the contact's force and the loads it puts
// on both bodies.

#include <cmath>
#include <limits>

#include "bounce/dem/step_check.hpp"
#include "bounce/models/dem_law.hpp"

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
  const double* omega1 = nullptr;  ///< body 1's angular velocity [rad/s]
  const double* omega2 = nullptr;  ///< body 2's (nullptr: a wall, which does not turn)
  double radius1 = 0.0, radius2 = 0.0;  ///< [m] (radius2 = inf: a wall)
  double distance = 0.0;                ///< between the centres [m] (0 for a wall)
};


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
  /// Torques beyond the tangential force's lever arm (rolling, twisting, and the exact torques of
  /// W07's sliding spring) [N m].
  double torque1[3] = {0.0, 0.0, 0.0};
  double torque2[3] = {0.0, 0.0, 0.0};
  /// The rolling, sliding and twisting springs' energy at this step, and what each released in it
  /// by moving beyond its critical displacement [J].
  double spring_energy = 0.0;
  double rolling_dissipated = 0.0, sliding_dissipated = 0.0, twisting_dissipated = 0.0;
  bool finite() const {
    bool all = std::isfinite(normal);
    for (int d = 0; d < 3; d++) all = all && std::isfinite(tangential[d]) && std::isfinite(torque1[d]) && std::isfinite(torque2[d]);
    return all;
  }
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

/// The force on body 1 (body 2 takes -force) and the torques on both: the tangential force's, the
/// lever arm being each radius (as in BSHP96's (10)), plus the contact's own torques.
struct Loads {
  double force[3];
  double torque1[3];
  double torque2[3];
};

/// Two spheres at distance r > 0 (as pair granular takes them; the lever arm is the radius).
/// Inline: it runs once per neighbour pair and step.
inline Kinematics pair_kinematics(const Motion& i, const Motion& j, double r) {
  Kinematics k;
  const double rinv = 1.0 / r;
  for (int d = 0; d < 3; d++) k.n[d] = (i.x[d] - j.x[d]) * rinv;
  k.overlap = i.radius + j.radius - r;
  const double vr[3] = {i.v[0] - j.v[0], i.v[1] - j.v[1], i.v[2] - j.v[2]};
  k.vn = vr[0] * k.n[0] + vr[1] * k.n[1] + vr[2] * k.n[2];
  const double wr[3] = {i.radius * i.omega[0] + j.radius * j.omega[0], i.radius * i.omega[1] + j.radius * j.omega[1],
                        i.radius * i.omega[2] + j.radius * j.omega[2]};
  k.sliding[0] = vr[0] - k.vn * k.n[0] - (k.n[2] * wr[1] - k.n[1] * wr[2]);
  k.sliding[1] = vr[1] - k.vn * k.n[1] - (k.n[0] * wr[2] - k.n[2] * wr[0]);
  k.sliding[2] = vr[2] - k.vn * k.n[2] - (k.n[1] * wr[0] - k.n[0] * wr[1]);
  k.omega1 = i.omega, k.omega2 = j.omega, k.radius1 = i.radius, k.radius2 = j.radius, k.distance = r;
  return k;
}

/// A sphere and a flat wall whose normal into the box is `sign` (+1 or -1) along `axis`.
inline Kinematics wall_kinematics(const Motion& i, int axis, double sign, double overlap) {
  const double *v = i.v, *o = i.omega, r = i.radius;
  Kinematics k;
  k.n[0] = k.n[1] = k.n[2] = 0.0;
  k.n[axis] = sign;
  k.overlap = overlap;
  k.vn = sign * v[axis];
  // The contact point's velocity in the tangent plane: v + omega x (-R n).
  const double spin[3] = {-r * (o[1] * k.n[2] - o[2] * k.n[1]), -r * (o[2] * k.n[0] - o[0] * k.n[2]),
                          -r * (o[0] * k.n[1] - o[1] * k.n[0])};
  for (int d = 0; d < 3; d++) k.sliding[d] = v[d] + spin[d];
  k.sliding[axis] = 0.0;
  k.omega1 = o, k.radius1 = r, k.radius2 = std::numeric_limits<double>::infinity();
  return k;
}

// BSHP96 (10): the torque of F^T at the contact point, -R n x F^T on each body.
inline Loads loads(const ContactForce& c, const Kinematics& k, double radius1, double radius2) {
  Loads l;
  const double* ft = c.tangential;
  for (int d = 0; d < 3; d++) l.force[d] = k.n[d] * c.normal + ft[d];
  const double arm[3] = {k.n[1] * ft[2] - k.n[2] * ft[1], k.n[2] * ft[0] - k.n[0] * ft[2],
                         k.n[0] * ft[1] - k.n[1] * ft[0]};
  for (int d = 0; d < 3; d++) {
    l.torque1[d] = -(radius1 * arm[d]) + c.torque1[d];
    l.torque2[d] = -(radius2 * arm[d]) + c.torque2[d];
  }
  return l;
}

}  // namespace bounce::dem

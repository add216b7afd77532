// The contact's kinematics from the bodies' motion, and its loads on them (step_types.hpp).

#include <cmath>

#include "bounce/dem/step_types.hpp"

namespace bounce::dem {

bool ContactForce::finite() const {
  return std::isfinite(normal) && std::isfinite(tangential[0]) && std::isfinite(tangential[1]) &&
         std::isfinite(tangential[2]);
}

Kinematics pair_kinematics(const Motion& i, const Motion& j, double r) {
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
  return k;
}

Kinematics wall_kinematics(const Motion& i, int axis, double sign, double overlap) {
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
  return k;
}

// BSHP96 (10): the torque of F^T at the contact point, -R n x F^T on each body.
Loads loads(const ContactForce& c, const Kinematics& k, double radius1, double radius2) {
  Loads l;
  const double* ft = c.tangential;
  for (int d = 0; d < 3; d++) l.force[d] = k.n[d] * c.normal + ft[d];
  const double arm[3] = {k.n[1] * ft[2] - k.n[2] * ft[1], k.n[2] * ft[0] - k.n[0] * ft[2],
                         k.n[0] * ft[1] - k.n[1] * ft[0]};
  for (int d = 0; d < 3; d++) {
    l.torque1[d] = -(radius1 * arm[d]);
    l.torque2[d] = -(radius2 * arm[d]);
  }
  return l;
}

}  // namespace bounce::dem

// The tangential sub-model's step (tangential.hpp): BSHP96's laws on the contact's spring.

#include "bounce/dem/tangential.hpp"

#include <cmath>

namespace bounce::dem {

namespace {

// The spring turns with the contact: back into the tangent plane, its length kept.
void turn_spring(const double n[3], double* h) {
  const double along = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
  const double before = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  for (int k = 0; k < 3; k++) h[k] -= along * n[k];
  const double after = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  if (after > 0.0)
    for (int k = 0; k < 3; k++) h[k] *= before / after;
}

}  // namespace

void Tangential::step(const SubContext& c, State& state, ContactForce& out) {
  if (!c.law.tangential) return;
  const Kinematics& k = c.k;
  double* h = state.spring.data();
  if (c.s.update_history) turn_spring(k.n, h);
  // The sliding in the tangent plane to round-off: its O(1e-16) normal part would otherwise
  // grow the spring along n, which a tiny zeta0 turns into a normal force.
  const double along = k.sliding[0] * k.n[0] + k.sliding[1] * k.n[1] + k.sliding[2] * k.n[2];
  const double sliding[3] = {k.sliding[0] - along * k.n[0], k.sliding[1] - along * k.n[1],
                             k.sliding[2] - along * k.n[2]};
  models::tangential_step(*c.law.tangential, c.normal_force, c.previous_normal_force, c.g.effective_mass, sliding,
                          c.s.dt, c.s.update_history, h, out.tangential);
}

}  // namespace bounce::dem

/* The step of one contact (docs/lammps.md, Time integration: corrected and plain).

   LAMMPS's velocity Verlet is a leapfrog: the force of step n acts over [t_n - dt/2, t_n + dt/2],
   computed with the positions at t_n and the velocities at t_n - dt/2. With `corrected` three
   things make a collision second order in dt:
    * the rate of the overlap is predicted to t_n with this contact's last force,
      xi' = -v_n - (dt/2) F_last / m_eff (exact to O(dt^2) in a binary collision);
    * a contact that forms inside the step, phi dt before t_n, gets the impulse of its force over
      that time by Simpson's rule, plus F_n dt/2: phi (F_0 + 4 F_m + F_n)/6 + F_n/2, with F_0 at
      first touch (JKR's snap-on, viscoelastic-shifted's C0 (A xi')^{3/2}; 0 for Hertz) and F_m
      at half the overlap;
    * a contact that ends inside the step, theta dt after t_{n-1}, gets the impulse of its force
      from the last overlap to the release overlap by Simpson's rule, less the F_{n-1} dt/2 the
      last step already gave: theta (F_{n-1} + 4 F_m + F_r)/6 - F_{n-1}/2.
   Simpson's rule follows the force's sqrt(xi) and xi^{3/2} near xi = 0 closely (a trapezoid
   made the COR error 3x larger). phi and theta come from the overlap at the step before,
   xi_n + dt v_n (Verlet's drift is exactly dt v). `plain` computes the force as LAMMPS's own
   pair styles do. */

#include "contact_step.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bounce::lammps {

namespace {

// The force at the ends of a contact is taken this fraction of the step's overlap inside it:
// the limit there (viscoelastic-shifted jumps to C0 (A xi')^{3/2} at first touch; JKR to its
// snap-on force), finite where a law is singular at xi = 0 (adhesive-viscoelastic's xi^{-1/4}).
constexpr double inside = 1e-6;

// The normal force of a contact law (positive: repulsive); under the `force` end rule it is
// never attractive (the contact has ended where it first vanished).
double normal_force(const models::DemModel& law, const models::ContactGeometry& g, double overlap, double rate) {
  const double f = law.normal->force(g, overlap, rate);
  return law.end_rule == models::EndRule::force && f < 0.0 ? 0.0 : f;
}

// The spring turns with the contact: back into the tangent plane, its length kept.
void turn_spring(const double n[3], double* h) {
  const double along = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
  const double before = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  for (int k = 0; k < 3; k++) h[k] -= along * n[k];
  const double after = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  if (after > 0.0)
    for (int k = 0; k < 3; k++) h[k] *= before / after;
}

void clear(int& touch, double* history) {
  touch = 0;
  for (int k = 0; k < history_size; k++) history[k] = 0.0;
}

}  // namespace

bool ContactForce::finite() const {
  return std::isfinite(normal) && std::isfinite(tangential[0]) && std::isfinite(tangential[1]) &&
         std::isfinite(tangential[2]);
}

ContactForce contact_step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                          double release, const StepSettings& s, int& touch, double* history) {
  ContactForce out;
  const bool touching = touch != 0;
  const bool contact = k.overlap > 0.0 || (touching && k.overlap > release);
  const double before = k.overlap + s.dt * k.vn;  // the overlap at the step before
  if (!contact) {
    if (touching && s.corrected) {  // released inside the step, theta dt after the last one
      const double theta = before > k.overlap ? std::clamp((before - release) / (before - k.overlap), 0.0, 1.0) : 0.0;
      const double last = history[last_force];
      const double middle = normal_force(law, g, 0.5 * (before + release), -k.vn);
      const double end = normal_force(law, g, release + inside * (before - release), -k.vn);
      out.normal = theta * (last + 4.0 * middle + end) / 6.0 - 0.5 * last;
    }
    clear(touch, history);
    return out;
  }
  touch = 1;
  const double previous = history[last_force];
  const double rate = -k.vn - (s.corrected ? 0.5 * s.dt * previous / g.effective_mass : 0.0);
  const double fn = normal_force(law, g, k.overlap, rate);
  if (s.update_history) history[last_force] = fn;
  if (fn > 0.0 && k.overlap > 0.0) out.period_steps = std::numbers::pi * std::sqrt(g.effective_mass * k.overlap / fn) / s.dt;
  if (law.tangential) {
    if (s.update_history) turn_spring(k.n, history);
    // The sliding in the tangent plane to round-off: its O(1e-16) normal part would otherwise
    // grow the spring along n, which a tiny zeta0 turns into a normal force.
    const double along = k.sliding[0] * k.n[0] + k.sliding[1] * k.n[1] + k.sliding[2] * k.n[2];
    const double sliding[3] = {k.sliding[0] - along * k.n[0], k.sliding[1] - along * k.n[1],
                               k.sliding[2] - along * k.n[2]};
    models::tangential_step(*law.tangential, fn, touching ? previous : fn, g.effective_mass, sliding, s.dt,
                            s.update_history, history, out.tangential);
  }
  out.normal = fn;
  if (s.corrected && !touching) {  // formed inside the step, phi dt before now (or overlapping already)
    const double phi = before < 0.0 ? k.overlap / (k.overlap - before) : 1.0;
    const double first = normal_force(law, g, inside * k.overlap, rate);
    const double middle = normal_force(law, g, 0.5 * k.overlap, rate);
    out.normal = phi * (first + 4.0 * middle + fn) / 6.0 + 0.5 * fn;
  }
  return out;
}

}  // namespace bounce::lammps

// The normal step of a force law's contact (docs/lammps.md, Time integration: corrected and plain).
//
// Velocity Verlet's force of step n acts over [t_n - dt/2, t_n + dt/2], computed with the
// positions at t_n and the velocities at t_n - dt/2. `corrected` makes a collision second order
// in dt: the rate is predicted to t_n with the last force, xi' = -v_n - (dt/2) F_last/m_eff; a
// contact that forms (ends) inside the step gets the impulse of its force over the part of the
// step it lasted, by Simpson's rule, which follows the force's sqrt(xi) and xi^{3/2} near xi = 0.
// `plain` computes the force as LAMMPS's own pair styles do.

#include <algorithm>
#include <cmath>

#include "bounce/dem/normal_step.hpp"
#include "step_parts.hpp"

namespace bounce::dem {

namespace {

// The force at the ends of a contact is taken this fraction of the step's overlap inside it: the
// limit there, finite where a law is singular at xi = 0 (adhesive-viscoelastic's xi^{-1/4}).
constexpr double inside = 1e-6;

// The normal force (positive: repulsive); under the `force` end rule never attractive (the
// contact has ended where it first vanished).
double normal_force(const models::DemModel& law, const models::ContactGeometry& g, double overlap, double rate) {
  const double f = law.normal->force(g, overlap, rate);
  return law.end_rule == models::EndRule::force && f < 0.0 ? 0.0 : f;
}

// The impulse of a contact released inside the step, theta dt after the last one, from the last
// overlap to the release overlap (Simpson's rule), less the F_{n-1} dt/2 the last step gave.
double release_impulse(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                       double before, double release, double last) {
  const double theta = before > k.overlap ? std::clamp((before - release) / (before - k.overlap), 0.0, 1.0) : 0.0;
  const double middle = normal_force(law, g, 0.5 * (before + release), -k.vn);
  const double end = normal_force(law, g, release + inside * (before - release), -k.vn);
  return theta * (last + 4.0 * middle + end) / 6.0 - 0.5 * last;
}

}  // namespace

NormalStep normal_step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                       const StepSettings& s, bool& touching, NormalState& normal, CrackStepState& crack,
                       ContactForce& out) {
  if (law.crack) return detail::crack_step(law, g, k, s, touching, normal, crack, out);
  const bool touched = touching;
  const double snap = law.normal->snap_overlap(g);  // where a contact forms (0: touching)
  const double release = k.overlap > 0.0 ? 0.0 : law.normal->release_overlap(g);
  const bool contact = k.overlap > snap || (touched && k.overlap > release);
  const double before = k.overlap + s.dt * k.vn;  // the overlap at the step before
  if (!contact) {
    if (touched && s.corrected) out.normal = release_impulse(law, g, k, before, release, normal.last_force);
    return {};
  }
  touching = true;
  const double previous = normal.last_force;
  const double rate = -k.vn - (s.corrected ? 0.5 * s.dt * previous / g.effective_mass : 0.0);
  const double fn = normal_force(law, g, k.overlap, rate);
  if (s.update_history) normal.last_force = fn;
  if (s.update_history && check_due(k.overlap, normal.checked_overlap))
    out.check = check_step(*law.normal, g, k.overlap, rate, s.dt, s.corrected ? 1.0 : 0.5);
  out.normal = fn;
  if (s.corrected && !touched) {  // formed inside the step, phi dt before now (or within reach already)
    const double phi = before < snap ? (k.overlap - snap) / (k.overlap - before) : 1.0;
    const double first = normal_force(law, g, snap + inside * (k.overlap - snap), rate);
    const double middle = normal_force(law, g, 0.5 * (snap + k.overlap), rate);
    out.normal = phi * (first + 4.0 * middle + fn) / 6.0 + 0.5 * fn;
  }
  return {true, fn, touched ? previous : fn};
}

}  // namespace bounce::dem

/* The step of one contact (docs/lammps.md, Time integration: corrected and plain).

   LAMMPS's velocity Verlet is a leapfrog: the force of step n acts over [t_n - dt/2, t_n + dt/2],
   computed with the positions at t_n and the velocities at t_n - dt/2. With `corrected` three
   things make a collision second order in dt:
    * the rate of the overlap is predicted to t_n with this contact's last force,
      xi' = -v_n - (dt/2) F_last / m_eff (exact to O(dt^2) in a binary collision);
    * a contact that forms inside the step, phi dt before t_n, gets the impulse of its force over
      that time by Simpson's rule, plus F_n dt/2: phi (F_0 + 4 F_m + F_n)/6 + F_n/2, with F_0 at
      first touch (JKR's snap-on, viscoelastic-shifted's C0 (A xi')^{3/2}; 0 for Hertz) and F_m
      half-way; a law whose contact forms before touching (Maugis-Dugdale's snap-on at -h0) forms
      it at its snap overlap instead of 0;
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

void clear(int& touch, double* history, int size = history_size) {
  touch = 0;
  for (int k = 0; k < size; k++) history[k] = 0.0;
}

// The tangential force, of the normal force fn (previous: the last step's).
void tangential(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                const StepSettings& s, double fn, double previous, double* history, ContactForce& out) {
  if (!law.tangential) return;
  if (s.update_history) turn_spring(k.n, history);
  // The sliding in the tangent plane to round-off: its O(1e-16) normal part would otherwise
  // grow the spring along n, which a tiny zeta0 turns into a normal force.
  const double along = k.sliding[0] * k.n[0] + k.sliding[1] * k.n[1] + k.sliding[2] * k.n[2];
  const double sliding[3] = {k.sliding[0] - along * k.n[0], k.sliding[1] - along * k.n[1],
                             k.sliding[2] - along * k.n[2]};
  models::tangential_step(*law.tangential, fn, previous, g.effective_mass, sliding, s.dt, s.update_history, history,
                          out.tangential);
}

/* The step in which one crack step breaks a contact (K13's run-away), with `corrected`: from the
   last step's state the crack moves through 16 stretches of the step (the run-away is steep, one
   crack step of the whole would time it badly), and in the stretch where it breaks the break is
   found by bisection. The impulse up to there is the trapezoidal rule's on the stretches, less
   the F_{n-1} dt/2 the last step already gave and the force `owed` back; all the energy of the
   contact at the break is the crack's. `state` is the last step's (advance with
   Refinement::unless_broken leaves it so). Returns whether it broke inside the step; where the
   stretches hold it to the step's end, `state` becomes their end state. */
template <class ForceAt>
bool break_inside_step(const models::CrackContactLaw& crack, const models::ContactGeometry& g, double before,
                       double overlap, const StepSettings& s, const double* history, double owed, const ForceAt& force_at,
                       ContactForce& out, models::CrackState& state) {
  models::CrackState now = state;
  const double f_last = history[last_force];
  auto overlap_at = [&](double theta) { return before + theta * (overlap - before); };
  auto advance = [&](double from, double length, models::CrackState& moved) {
    return crack.advance(g, overlap_at(from), overlap_at(from + length), length * s.dt, moved, models::Refinement::none);
  };
  double impulse = 0.0, released = 0.0, theta = 0.0, f_from = f_last;
  constexpr double stretch = 1.0 / 16.0;
  for (; theta < 1.0; theta += stretch) {
    models::CrackState next = now;
    const models::CrackAdvance a = advance(theta, stretch, next);
    if (a.broken) {
      double lo = 0.0, hi = stretch;
      for (int i = 0; i < 12; i++) {  // to 2^-16 of the step
        const double mid = 0.5 * (lo + hi);
        models::CrackState probe = now;
        (advance(theta, mid, probe).broken ? hi : lo) = mid;
      }
      next = now;
      released += advance(theta, lo, next).dissipated;
      const double f_to = force_at(overlap_at(theta + lo), next);
      impulse += 0.5 * lo * (f_from + f_to);
      released += crack.elastic_energy(g, overlap_at(theta + lo), next) + crack.surface_energy(g, next);
      out.normal = impulse - 0.5 * f_last - owed;
      out.bulk_dissipated = 0.5 * (theta + lo) * s.dt * history[last_bulk_force] * history[last_rate];
      out.crack_dissipated = released;
      return true;
    }
    released += a.dissipated;
    const double f_to = force_at(overlap_at(theta + stretch), next);
    impulse += 0.5 * stretch * (f_from + f_to);
    f_from = f_to;
    now = next;
  }
  state = now;
  return false;
}

/* A crack law's contact (krijt, docs/lammps.md, K13's contact in LAMMPS). Its radius a is the
   history's; each step moves it to the step's overlap by the law's stable update, then
     F = F_E(a, xi) + D(a) xi',
   with xi' at t_n taken implicitly, as the trapezoidal rule does: xi'_n = -v_n - (dt/2) F_n / m_eff
   with the half-step v_n LAMMPS has, solved for xi'_n since F is linear in it. An explicit rate
   would be unstable once D dt / m_eff > 2 (T_vis >~ 1e-9 s for micrometre ice at t_H/100).
   The contact forms at overlap 0 (K13 appendix B) and ends where the crack runs away, wherever
   the overlap is then. With `corrected`, the step where it forms gets the impulse of the part
   phi dt it lasted, and the step where it breaks that of the part theta dt before the break,
   each by the trapezoidal rule on stretches of the step in which the crack moves (below). */
class CrackContactStep {
 public:
  CrackContactStep(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                   const StepSettings& s, int& touch, double* history)
      : law_(law), crack_(*law.crack), g_(g), k_(k), s_(s), touch_(touch), history_(history),
        touching_(touch != 0), before_(k.overlap + s.dt * k.vn), half_step_over_m_(0.5 * s.dt / g.effective_mass),
        state_{history[crack_state], history[crack_state + 1], history[crack_state + 2], history[crack_state + 3]},
        owed_(touching_ && s.update_history ? history[lent_force] : 0.0) {}
  ContactForce run();

 private:
  // The force at overlap xi, and the bulk force's power D xi'^2 there.
  struct Point {
    double force, bulk;
  };
  // The rate at t_n of a force F_E + D xi' (the trapezoidal rule), or LAMMPS's half-step one.
  double rate(double elastic, double damping) const {
    return s_.corrected ? (-k_.vn - half_step_over_m_ * elastic) / (1.0 + half_step_over_m_ * damping) : -k_.vn;
  }
  Point at(double xi, const models::CrackState& state) const {
    const auto [elastic, damping] = crack_.force(g_, xi, state);
    const double r = rate(elastic, damping);
    return Point{elastic + damping * r, damping * r * r};
  }
  void form();
  void record(double elastic, double damping, double xi_rate, ContactForce& out);

  const models::DemModel& law_;
  const models::CrackContactLaw& crack_;
  const models::ContactGeometry& g_;
  const Kinematics& k_;
  const StepSettings& s_;
  int& touch_;
  double* history_;
  const bool touching_;
  const double before_;  // the overlap at the step before
  const double half_step_over_m_;
  models::CrackState state_;
  const double owed_;
  models::CrackAdvance advance_;
  double formation_impulse_ = 0.0;  // over the part of the step since the contact formed, / dt
  double lent_ = 0.0;               // see run()
  double formation_bulk_ = 0.0;     // the bulk force's work since the contact formed
};

// It formed phi dt before now (K13 appendix B), at overlap 0, and its crack is fastest there. Its
// radius moves through stretches of that time that double from 2^-12 of it to 1/16, then
// stretches of 1/16 (BDF2's second order needs a uniform step): 23 crack steps, once per contact.
// One step of backward Euler would leave a 15 % short of the crack law's at t_H/100 (micrometre
// ice, T_vis = 1e-12 s), doubling stretches to the end 3 % short. The energy the crack releases is
// counted where it moves, and the impulse of the step is the trapezoidal rule's on the same
// stretches, so that the work of the elastic force is the one the energy budget counts.
void CrackContactStep::form() {
  double released = 0.0;
  state_ = crack_.form(g_, released);
  const double phi = s_.corrected && before_ < 0.0 ? k_.overlap / (k_.overlap - before_) : 1.0;  // the part it lasted
  double from = 0.0;
  Point at_from = at(0.0, state_);
  for (int j = -12; from < 1.0 && !advance_.broken; j++) {
    const double to = j <= -4 ? std::ldexp(1.0, j) : from + 1.0 / 16.0;
    const models::CrackAdvance a = crack_.advance(g_, from * k_.overlap, to * k_.overlap, (to - from) * phi * s_.dt,
                                                  state_, models::Refinement::none);
    released += a.dissipated;
    advance_.broken = a.broken;
    const Point at_to = at(to * k_.overlap, state_);
    const double mean = 0.5 * (at_from.force + at_to.force);
    formation_impulse_ += mean * (to - from) * phi;
    lent_ += mean * (to - from) * phi * (1.0 - 0.5 * (from + to)) * phi;
    // The bulk force's work on the same stretches (a grows fastest first: a straight line
    // from 0 to its end value missed 1e-2 of the impact energy at T_vis = 1e-10 s).
    formation_bulk_ += 0.5 * (at_from.bulk + at_to.bulk) * (to - from) * phi * s_.dt;
    at_from = at_to;
    from = to;
  }
  advance_.dissipated = released;
}

// The history at the step's end and the energies of the step.
void CrackContactStep::record(double elastic, double damping, double xi_rate, ContactForce& out) {
  const double elastic_energy = crack_.elastic_energy(g_, k_.overlap, state_), surface = crack_.surface_energy(g_, state_);
  out.elastic = elastic_energy;
  out.surface = surface;
  if (!s_.update_history) return;
  double* h = history_;
  h[crack_state] = state_.contact_radius;
  h[crack_state + 1] = state_.previous_radius;
  h[crack_state + 2] = state_.previous_step;
  h[crack_state + 3] = state_.older_radius;
  if (touching_) {
    // The crack's share, as velocity Verlet does the work: the elastic force's work over the
    // step, (F_E,n-1 + F_E,n)/2 (xi_n - xi_n-1), less the change of the stored energy U. Like
    // the law's own estimate (the release at fixed overlap, averaged over the step's two
    // overlaps) it is K13's -int dU/da a' dt to second order, but it leaves no remainder: that
    // one differs by E* (a_n - a_n-1)(xi_n - xi_n-1)^2 / 2 a step, 2e-3 of the impact energy
    // where a relaxes fast after a snap-on (micrometre ice at half the sticking velocity).
    const double elastic_before = h[last_force] - h[last_bulk_force];
    out.crack_dissipated = h[last_stored] - (elastic_energy + surface) + 0.5 * (elastic_before + elastic) * (k_.overlap - before_);
  }
  h[last_stored] = elastic_energy + surface;
  h[last_force] = elastic + damping * xi_rate;
  // The bulk force's work as velocity Verlet does it: from t_{n-1} to t_n the kinetic energy
  // at whole steps changes by exactly (dt/4)(F_{n-1} + F_n)(xi'_{n-1} + xi'_n), so that this
  // part of it is the energy the bulk force took (a rectangle rule, D_n xi'_n^2 dt, is off by
  // a first-order (dt/2) int D' xi'^2 dt as a grows: 1e-2 of the impact energy at t_H/100).
  const double bulk = damping * xi_rate;
  out.bulk_dissipated = touching_ ? 0.25 * s_.dt * (h[last_bulk_force] + bulk) * (h[last_rate] + xi_rate) : formation_bulk_;
  h[last_bulk_force] = bulk;
  h[last_rate] = xi_rate;
}

ContactForce CrackContactStep::run() {
  ContactForce out;
  if (!touching_ && k_.overlap <= 0.0) {
    clear(touch_, history_, crack_history_size);
    return out;
  }
  if (!touching_) {
    form();
  } else if (s_.update_history) {
    // (With `corrected` a step that one crack step breaks is divided by break_inside_step, which
    // times the break, into the 16 stretches the law would divide it into.)
    advance_ = crack_.advance(g_, before_, k_.overlap, s_.dt, state_,
                              s_.corrected ? models::Refinement::unless_broken : models::Refinement::full);
  }
  if (s_.update_history) out.crack_dissipated = advance_.dissipated;
  if (advance_.broken && s_.corrected && touching_) {
    const auto force_at = [&](double xi, const models::CrackState& state) { return at(xi, state).force; };
    if (break_inside_step(crack_, g_, before_, k_.overlap, s_, history_, owed_, force_at, out, state_)) {
      clear(touch_, history_, crack_history_size);
      return out;
    }
    // Its stretches held the contact to the step's end where one crack step broke it: their end
    // is the step's, in `state_` (the next step's crack update, after these stretches, is backward
    // Euler's).
    advance_.broken = false;
  }
  if (advance_.broken) {  // K13's end, inside this step
    clear(touch_, history_, crack_history_size);
    return out;
  }
  if (s_.update_history) touch_ = 1;  // (in LAMMPS's setup a new contact forms at the first step)
  const auto [elastic, damping] = crack_.force(g_, k_.overlap, state_);
  const double xi_rate = rate(elastic, damping);
  const double fn = elastic + damping * xi_rate;
  const double previous = history_[last_force];
  record(elastic, damping, xi_rate, out);
  // Its rate is implicit with `corrected`: only the stiffness bounds the step.
  if (s_.update_history && check_due(k_.overlap, history_[checked_overlap]))
    out.check = check_crack_step(crack_, g_, k_.overlap, state_, {elastic, damping}, s_.dt, s_.corrected ? 0.0 : 0.5);
  tangential(law_, g_, k_, s_, fn, touching_ ? previous : fn, history_, out);
  out.normal = fn;
  // The forming step's impulse; and the displacement its force would have made by now, which
  // the positions LAMMPS has at t_n lack (the force began before): (1/m) int (t_n - t) F dt, a
  // few 1e-3 of the impact energy in a snap-on. It is lent as a force m eps / dt^2 that moves
  // the pair by eps at the next step, which pays it back (momentum is unchanged after both).
  if (s_.corrected && !touching_) {
    out.normal = formation_impulse_ + 0.5 * fn + lent_;
    if (s_.update_history) history_[lent_force] = lent_;
  } else {
    out.normal -= owed_;
    if (s_.update_history) history_[lent_force] = 0.0;
  }
  return out;
}

}  // namespace

bool ContactForce::finite() const {
  return std::isfinite(normal) && std::isfinite(tangential[0]) && std::isfinite(tangential[1]) &&
         std::isfinite(tangential[2]);
}

ContactForce contact_step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                          double release, const StepSettings& s, int& touch, double* history) {
  if (law.crack) return CrackContactStep(law, g, k, s, touch, history).run();
  ContactForce out;
  const bool touching = touch != 0;
  const double snap = law.normal->snap_overlap(g);  // where a contact forms (0: touching)
  const bool contact = k.overlap > snap || (touching && k.overlap > release);
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
  if (s.update_history && check_due(k.overlap, history[checked_overlap]))
    out.check = check_step(*law.normal, g, k.overlap, rate, s.dt, s.corrected ? 1.0 : 0.5);
  tangential(law, g, k, s, fn, touching ? previous : fn, history, out);
  out.normal = fn;
  if (s.corrected && !touching) {  // formed inside the step, phi dt before now (or within reach already)
    const double phi = before < snap ? (k.overlap - snap) / (k.overlap - before) : 1.0;
    const double first = normal_force(law, g, snap + inside * (k.overlap - snap), rate);
    const double middle = normal_force(law, g, 0.5 * (snap + k.overlap), rate);
    out.normal = phi * (first + 4.0 * middle + fn) / 6.0 + 0.5 * fn;
  }
  return out;
}

}  // namespace bounce::lammps

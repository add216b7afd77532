// The step of a crack law's contact (krijt; docs/lammps.md, K13's contact in LAMMPS). Its radius
// a is the state's; each step moves it to the step's overlap by the law's stable update, then
//   F = F_E(a, xi) + D(a) xi',
// with xi' at t_n implicit, as the trapezoidal rule takes it: xi'_n = -v_n - (dt/2) F_n / m_eff,
// solved for xi'_n since F is linear in it (an explicit rate is unstable once D dt/m_eff > 2).
// The contact forms at overlap 0 (K13 appendix B) and ends where the crack runs away. With
// `corrected`, the steps where it forms and breaks get the impulse of the part of the step it
// lasted, by the trapezoidal rule on stretches of the step in which the crack moves.

#include <cmath>

#include "step_parts.hpp"

namespace bounce::dem::detail {

namespace {

/* The step in which one crack step breaks a contact (K13's run-away), with `corrected`: the crack
   moves through 16 stretches of the step, and in the stretch where it breaks the break is found by
   bisection. The impulse up to there is the trapezoidal rule's on the stretches, less the
   F_{n-1} dt/2 the last step gave and the force `owed` back; all the energy of the contact at the
   break is the crack's. Returns whether it broke inside the step; where the stretches hold it to
   the step's end, `state` becomes their end state. */
template <class ForceAt>
bool break_inside_step(const models::DemCrackLaw& crack, const models::ContactGeometry& g, double before,
                       double overlap, const StepSettings& s, double f_last, const CrackStepState& history,
                       double owed, const ForceAt& force_at, ContactForce& out, models::CrackState& state) {
  models::CrackState now = state;
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
      out.bulk_dissipated = 0.5 * (theta + lo) * s.dt * history.last_bulk_force * history.last_rate;
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

class CrackContactStep {
 public:
  CrackContactStep(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                   const StepSettings& s, bool& touching, NormalState& normal, CrackStepState& history)
      : crack_(*law.crack), g_(g), k_(k), s_(s), touching_now_(touching), normal_(normal), history_(history),
        touching_(touching), before_(k.overlap + s.dt * k.vn), half_step_over_m_(0.5 * s.dt / g.effective_mass),
        radius_(history.crack), owed_(touching && s.update_history ? history.lent_force : 0.0) {}
  NormalStep run(ContactForce& out);

 private:
  // The force at overlap xi, and the bulk force's power D xi'^2 there.
  struct Point {
    double force, bulk;
  };
  // The rate at t_n of a force F_E + D xi' (the trapezoidal rule), or the half-step one.
  double rate(double elastic, double damping) const {
    return s_.corrected ? (-k_.vn - half_step_over_m_ * elastic) / (1.0 + half_step_over_m_ * damping) : -k_.vn;
  }
  Point at(double xi, const models::CrackState& radius) const {
    const auto [elastic, damping] = crack_.force(g_, xi, radius);
    const double r = rate(elastic, damping);
    return Point{elastic + damping * r, damping * r * r};
  }
  void form();
  bool broke(ContactForce& out);
  void record(double elastic, double damping, double xi_rate, ContactForce& out);

  const models::DemCrackLaw& crack_;
  const models::ContactGeometry& g_;
  const Kinematics& k_;
  const StepSettings& s_;
  bool& touching_now_;
  NormalState& normal_;
  CrackStepState& history_;
  const bool touching_;
  const double before_;  // the overlap at the step before
  const double half_step_over_m_;
  models::CrackState radius_;  // the crack's state as the step moves it
  const double owed_;
  models::CrackAdvance advance_;
  double formation_impulse_ = 0.0;  // over the part of the step since the contact formed, / dt
  double lent_ = 0.0;               // see run()
  double formation_bulk_ = 0.0;     // the bulk force's work since the contact formed
};

// It formed phi dt before now (K13 appendix B), at overlap 0, where its crack is fastest: its
// radius moves through stretches of that time that double from 2^-12 of it to 1/16, then
// stretches of 1/16 (BDF2's second order needs a uniform step). The energy the crack releases is
// counted where it moves, and the impulse is the trapezoidal rule's on the same stretches, so that
// the work of the elastic force is the one the energy budget counts.
void CrackContactStep::form() {
  double released = 0.0;
  radius_ = crack_.form(g_, released);
  const double phi = s_.corrected && before_ < 0.0 ? k_.overlap / (k_.overlap - before_) : 1.0;  // the part it lasted
  double from = 0.0;
  Point at_from = at(0.0, radius_);
  for (int j = -12; from < 1.0 && !advance_.broken; j++) {
    const double to = j <= -4 ? std::ldexp(1.0, j) : from + 1.0 / 16.0;
    const models::CrackAdvance a = crack_.advance(g_, from * k_.overlap, to * k_.overlap, (to - from) * phi * s_.dt,
                                                  radius_, models::Refinement::none);
    released += a.dissipated;
    advance_.broken = a.broken;
    const Point at_to = at(to * k_.overlap, radius_);
    const double mean = 0.5 * (at_from.force + at_to.force);
    formation_impulse_ += mean * (to - from) * phi;
    lent_ += mean * (to - from) * phi * (1.0 - 0.5 * (from + to)) * phi;
    formation_bulk_ += 0.5 * (at_from.bulk + at_to.bulk) * (to - from) * phi * s_.dt;  // a grows fastest first
    at_from = at_to;
    from = to;
  }
  advance_.dissipated = released;
}

// The state at the step's end and the energies of the step.
void CrackContactStep::record(double elastic, double damping, double xi_rate, ContactForce& out) {
  const double elastic_energy = crack_.elastic_energy(g_, k_.overlap, radius_), surface = crack_.surface_energy(g_, radius_);
  out.elastic = elastic_energy;
  out.surface = surface;
  if (!s_.update_history) return;
  NormalState& normal = normal_;
  CrackStepState& h = history_;
  h.crack = radius_;
  // The crack's share, as velocity Verlet does the work: the elastic force's trapezoidal work
  // over the step less the change of the stored energy (K13's -int dU/da a' dt to second order,
  // with no remainder; docs/lammps.md, Validation of krijt).
  if (touching_) {
    const double elastic_before = normal.last_force - h.last_bulk_force;
    out.crack_dissipated = h.last_stored - (elastic_energy + surface) + 0.5 * (elastic_before + elastic) * (k_.overlap - before_);
  }
  h.last_stored = elastic_energy + surface;
  normal.last_force = elastic + damping * xi_rate;
  // The bulk force's work as velocity Verlet does it: the kinetic energy at whole steps changes by
  // exactly (dt/4)(F_{n-1} + F_n)(xi'_{n-1} + xi'_n) from t_{n-1} to t_n.
  const double bulk = damping * xi_rate;
  out.bulk_dissipated = touching_ ? 0.25 * s_.dt * (h.last_bulk_force + bulk) * (h.last_rate + xi_rate) : formation_bulk_;
  h.last_bulk_force = bulk;
  h.last_rate = xi_rate;
}

// Moves the crack over the step (forms it first); true where the contact ended in it.
bool CrackContactStep::broke(ContactForce& out) {
  if (!touching_) {
    form();
  } else if (s_.update_history) {
    // (With `corrected` a step that one crack step breaks is divided by break_inside_step.)
    advance_ = crack_.advance(g_, before_, k_.overlap, s_.dt, radius_,
                              s_.corrected ? models::Refinement::unless_broken : models::Refinement::full);
  }
  if (s_.update_history) out.crack_dissipated = advance_.dissipated;
  if (advance_.broken && s_.corrected && touching_) {
    const auto force_at = [&](double xi, const models::CrackState& radius) { return at(xi, radius).force; };
    if (break_inside_step(crack_, g_, before_, k_.overlap, s_, normal_.last_force, history_, owed_, force_at, out,
                          radius_))
      return true;
    advance_.broken = false;  // its stretches held it to the step's end, in radius_
  }
  return advance_.broken;  // K13's end, inside this step
}

NormalStep CrackContactStep::run(ContactForce& out) {
  if ((!touching_ && k_.overlap <= 0.0) || broke(out)) return {};
  if (s_.update_history) touching_now_ = true;  // (in LAMMPS's setup a new contact forms at the first step)
  NormalState& normal = normal_;
  const auto [elastic, damping] = crack_.force(g_, k_.overlap, radius_);
  const double xi_rate = rate(elastic, damping);
  const double fn = elastic + damping * xi_rate;
  const double previous = normal.last_force;
  record(elastic, damping, xi_rate, out);
  // Its rate is implicit with `corrected`: only the stiffness bounds the step.
  if (s_.update_history && check_due(k_.overlap, normal.checked_overlap))
    out.check = check_crack_step(crack_, g_, k_.overlap, radius_, {elastic, damping}, s_.dt, s_.corrected ? 0.0 : 0.5);
  out.normal = fn;
  // The forming step's impulse; and the displacement its force would have made by now, which the
  // positions at t_n lack, lent as a force that the next step pays back (momentum unchanged).
  if (s_.corrected && !touching_) {
    out.normal = formation_impulse_ + 0.5 * fn + lent_;
    if (s_.update_history) history_.lent_force = lent_;
  } else {
    out.normal -= owed_;
    if (s_.update_history) history_.lent_force = 0.0;
  }
  return {true, fn, touching_ ? previous : fn};
}

}  // namespace

NormalStep crack_step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                      const StepSettings& s, bool& touching, NormalState& normal, CrackStepState& crack,
                      ContactForce& out) {
  return CrackContactStep(law, g, k, s, touching, normal, crack).run(out);
}

}  // namespace bounce::dem::detail

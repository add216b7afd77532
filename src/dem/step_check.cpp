// The explicit step's check at a contact (step_check.hpp, docs/lammps.md, Time step).

#include "bounce/dem/step_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace bounce::dem {

namespace {

// The relative step of the difference quotients: k and D are wanted to a few digits.
constexpr double probe = 1e-6;

StepCheck rate_stability(double stiffness, double damping, double mass, double dt, double q) {
  StepCheck c;
  c.stiffness = stiffness;
  c.damping = damping;
  c.weight = q;
  c.effective_mass = mass;
  c.elastic_term = 0.25 * std::max(stiffness, 0.0) * dt * dt / mass;
  c.stability = c.elastic_term + q * std::max(damping, 0.0) * dt / mass;
  return c;
}

}  // namespace

// stability(dt') = e (dt'/dt)^2 + d (dt'/dt) with this dt's elastic and damping terms: its root at 1.
double StepCheck::largest_step(double dt) const {
  const double e = elastic_term, d = stability - elastic_term;
  if (e > 0.0) return dt * (2.0 / (d + std::sqrt(d * d + 4.0 * e)));
  return d > 0.0 ? dt / d : 0.0;
}

std::string StepCheck::describe(double dt) const {
  const double period = stiffness > 0.0 ? 2.0 * std::numbers::pi * std::sqrt(effective_mass / stiffness) / dt : 0.0;
  const double relaxation = damping > 0.0 ? effective_mass / (damping * dt) : 0.0;
  return fmt::format("stiffness k = {:.3g} N/m, damping D = {:.3g} kg/s, m_eff = {:.3g} kg: a period 2 pi sqrt(m_eff/k) "
                     "of {} and a damping time m_eff/D of {}, and (k dt^2/m_eff)/4 + {} D dt/m_eff = {:.3g} at dt = {:.6g} "
                     "s (stable below 1: dt < {:.3g} s)",
                     stiffness, damping, effective_mass, period > 0.0 ? fmt::format("{:.3g} steps", period) : "none",
                     relaxation > 0.0 ? fmt::format("{:.3g} steps", relaxation) : "none", weight, stability, dt,
                     largest_step(dt));
}

bool check_due(double overlap, double& checked) {
  if (overlap <= 0.0 || overlap <= recheck * checked) return false;
  checked = overlap;
  return true;
}

// k = dF/dxi at rate 0 (forward difference) and D the force's change with the rate, from 0 to the
// contact's rate (or to xi/dt where it is 0): exact for bounce's laws linear in the rate.
StepCheck check_step(const models::DemLaw& law, const models::ContactGeometry& g, double overlap, double rate,
                     double dt, double q) {
  const double at_rest = law.force(g, overlap, 0.0);
  const double h = probe * overlap;
  const double stiffness = (law.force(g, overlap + h, 0.0) - at_rest) / h;
  const double probe_rate = std::abs(rate) > 0.0 ? std::abs(rate) : overlap / dt;
  const double damping = (law.force(g, overlap, probe_rate) - at_rest) / probe_rate;
  return rate_stability(stiffness, damping, g.effective_mass, dt, q);
}

StepCheck check_crack_step(const models::DemCrackLaw& law, const models::ContactGeometry& g, double overlap,
                           const models::CrackState& s, const models::DemCrackLaw::Force& force, double dt,
                           double q) {
  const double h = probe * overlap;
  const double stiffness = (law.force(g, overlap + h, s).elastic - force.elastic) / h;
  return rate_stability(stiffness, force.damping, g.effective_mass, dt, q);
}

}  // namespace bounce::dem

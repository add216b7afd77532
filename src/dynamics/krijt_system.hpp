#pragma once
// Private: K13's equations as a stiff system (scaled state delta, delta', a and the
// two dissipated energies), shared by dynamics/adhesive_collision.cpp and the tests.

#include <algorithm>
#include <cmath>
#include <numbers>


#include "bounce/contact/hertz.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/models/crack.hpp"
#include "bounce/models/krijt.hpp"
#include "bounce/pair/mixing.hpp"
#include "stiff.hpp"

namespace bounce::dynamics::detail {

constexpr double pi = std::numbers::pi;

// Units of the scaled problem: lengths from the larger of the Hertz overlap and the
// JKR separation overlap, speeds from the impact speed, energies from (1/2) m g^2.
struct Scales {
  double length;   // delta
  double radius;   // a
  double speed;    // delta'
  double time;     // length / speed
  double energy;   // (1/2) m g^2
};

// `release`: the overlap where an adhesive contact breaks (JKR's delta_c, or another branch's fold).
inline Scales scales_for(const models::AdhesivePair& p, double speed, double release) {
  const double rho = hertz_constant(p.effective_modulus, p.effective_radius);
  const double xi0 = contact::hertz::reference_overlap(rho, p.effective_mass, speed);
  const contact::jkr::Parameters j{p.effective_radius, p.effective_modulus, p.surface_energy};
  Scales s;
  s.length = std::max(xi0, std::abs(release));
  s.radius = std::max(std::sqrt(p.effective_radius * xi0), contact::jkr::equilibrium_contact_radius(j));
  s.speed = speed;
  s.time = s.length / speed;
  s.energy = 0.5 * p.effective_mass * speed * speed;
  return s;
}
inline Scales scales_for(const models::AdhesivePair& p, double speed) {
  return scales_for(p, speed, contact::jkr::separation_overlap({p.effective_radius, p.effective_modulus, p.surface_energy}));
}

// Elastic Hertz contact time in the scaled units (a time scale for budgets and sampling).
inline double scaled_hertz_time(const models::AdhesivePair& p, double speed, const Scales& s) {
  const double rho = hertz_constant(p.effective_modulus, p.effective_radius);
  return contact::hertz::collision_time(rho, p.effective_mass, speed) / s.time;
}

// Where the crack runs (beta near k: closing at a speed that diverges; beta near 1/k:
// the run-away of the opening crack; or the whole pull-off of a crack so fast that a
// collapses from the JKR fold in 1e-12 of the contact time), a' is large and a(t)
// singular; a is then the better independent variable (detail::SwappedIndependent).
// The phases of a collision are `closing` (beta < 0.25, where a' >= 2.2 c), `time`,
// and `opening` (beta > 4, where a' <= -3.5 c, or beta > 1 with the contact
// shrinking at a relative rate |a'/a| above 1e3 per time unit L/g ~ t_H/3), with
// hysteresis (leave at 0.25; at beta < 3 and |a'/a| < 1e2) so that the phases cannot
// chatter and a' never vanishes inside an a phase. The equations are the same in
// every phase.
enum class Phase { time, closing, opening };
constexpr double closing_exit = 0.25, closing_entry = 0.2;
constexpr double opening_entry = 4.0, opening_exit = 3.0;
constexpr double collapse_entry = 1e3, collapse_exit = 1e2;  // |a'/a| in scaled time

class KrijtSystem final : public StiffSystem {
 public:
  KrijtSystem(const models::KrijtParameters& p, const Scales& s, bool stick_event, double break_margin)
      : p_(p), s_(s), c_(p.crack_speed_scale()), beta_break_((1.0 - break_margin) / p.k),
        stick_event_(stick_event) {
    const contact::jkr::Parameters j{p.effective_radius, p.effective_modulus, p.surface_energy};
    fold_overlap_ = contact::jkr::separation_overlap(j);
    fold_radius_ = contact::jkr::separation_contact_radius(j);
    fold_energy_ = models::contact_energy(p, fold_radius_, fold_overlap_) / s.energy;
    // The equations in the scaled variables (d, v, alpha) = (delta / L, delta' / g, a / a_s)
    // with time unit T = L / g, as polynomials with these coefficients (a step evaluates them
    // seven times: no division but the one of beta).
    const double e = p.effective_modulus, r = p.effective_radius, gamma = p.surface_energy;
    const double force = s.time / (p.effective_mass * s.speed);  // a force in scaled d v / d t
    force_overlap_ = force * 2.0 * e * s.radius * s.length;                        // K13 (2): 2 E* a delta
    force_cubic_ = force * 2.0 * e / (3.0 * r) * s.radius * s.radius * s.radius;  // K13 (2): 2 E* a^3 / (3R)
    force_rate_ = force * 2.0 * p.dissipative_constant * e * s.radius * s.speed;    // K13 (19)
    overlap_radius_ = s.length * r / (s.radius * s.radius);                       // delta R / a^2 -> d q / alpha^2
    beta_scale_ = e * s.radius * s.radius * s.radius / (2.0 * pi * r * r * gamma);  // K13 (14)
    crack_ = c_ * s.time / s.radius;                                             // K13 (16)-(17)
    crack_energy_ = 2.0 * pi * s.radius * gamma * c_ * s.time / s.energy;        // K13 (C.2)
    bulk_energy_ = 2.0 * p.dissipative_constant * e * s.radius * s.speed * s.speed * s.time / s.energy;  // K13 (C.3)
  }

  int size() const override { return 5; }

  struct Physical {
    double delta, rate, a, beta;
  };
  Physical physical(const double* y) const {
    return {y[0] * s_.length, y[1] * s_.speed, y[2] * s_.radius, y[2] > 0.0 ? beta_of(mismatch_of(y[0], y[2]), y[2]) : 0.0};
  }

  int rhs(double, const double* y, double* dydt) const override { return evaluate(y, dydt, nullptr); }
  int jacobian(double t, const double* y, double* j, double* dfdt) const override {
    double f[5];
    return linearize(t, y, f, j, dfdt, nullptr);
  }
  int linearize(double t, const double* y, double* f, double* j, double* dfdt, double* g) const override {
    if (dfdt != nullptr) std::fill(dfdt, dfdt + 5, 0.0);  // autonomous
    return evaluate(y, f, j, t, g);
  }
  /// U_CD and U_BD enter no right-hand side.
  unsigned quadratures() const override { return (1u << 3) | (1u << 4); }

 private:
  // The right-hand side and, unless j is null, the Jacobian: one evaluation of beta and of
  // the crack law for both (the engine asks for them together at every step).
  // With g, also the events at time t.
  int evaluate(const double* y, double* dydt, double* j, double t = 0.0, double* g = nullptr) const {
    const double d = y[0], v = y[1], alpha = y[2];
    if (!(alpha > 0.0)) return 1;  // recoverable: the engine retries a smaller step
    const double mismatch = mismatch_of(d, alpha);
    const double beta = beta_of(mismatch, alpha);
    if (!(beta > p_.k && beta * p_.k < 1.0)) return 1;
    const models::CrackSpeed f = models::crack_speed_function(beta, p_.k);
    if (g != nullptr) events(t, y, Physical{d * s_.length, v * s_.speed, alpha * s_.radius, beta}, f.value, g);
    dydt[0] = v;
    dydt[1] = -force_overlap_ * alpha * d + force_cubic_ * alpha * alpha * alpha - force_rate_ * alpha * v;  // K13 (20)
    dydt[2] = crack_ * f.value;                                                    // K13 (16)-(17)
    dydt[3] = crack_energy_ * alpha * (1.0 - beta) * f.value;                     // K13 (C.2)
    dydt[4] = bulk_energy_ * alpha * v * v;                                        // K13 (C.3)
    if (j == nullptr) return 0;
    // d beta / d d and d beta / d alpha from K13 (14).
    const double dbeta_dd = -2.0 * beta_scale_ * overlap_radius_ * mismatch / alpha;
    const double dbeta_dalpha = beta_scale_ * mismatch * (3.0 * alpha * alpha + overlap_radius_ * d) / (alpha * alpha);
    std::fill(j, j + 25, 0.0);  // columns: d, v, alpha, U_CD, U_BD
    j[0 * 5 + 1] = 1.0;
    j[1 * 5 + 0] = -force_overlap_ * alpha;
    j[1 * 5 + 1] = -force_rate_ * alpha;
    j[1 * 5 + 2] = -force_overlap_ * d + 3.0 * force_cubic_ * alpha * alpha - force_rate_ * v;
    j[2 * 5 + 0] = crack_ * f.derivative * dbeta_dd;
    j[2 * 5 + 2] = crack_ * f.derivative * dbeta_dalpha;
    // U_CD' = k alpha (1 - beta) f(beta)
    const double along = (1.0 - beta) * f.derivative - f.value;  // d[(1 - beta) f] / d beta
    j[3 * 5 + 0] = crack_energy_ * alpha * along * dbeta_dd;
    j[3 * 5 + 2] = crack_energy_ * ((1.0 - beta) * f.value + alpha * along * dbeta_dalpha);
    j[4 * 5 + 1] = 2.0 * bulk_energy_ * alpha * v;  // U_BD' = k alpha v^2
    j[4 * 5 + 2] = bulk_energy_ * v * v;
    return 0;
  }
  // K13 (14) in the scaled state (one formula for the equations and the events):
  // beta = beta_scale (alpha^2 - q d)^2 / alpha, the mismatch (a^2 - delta R) / a_s^2 = alpha^2 - q d.
  double mismatch_of(double d, double alpha) const { return alpha * alpha - overlap_radius_ * d; }
  double beta_of(double mismatch, double alpha) const { return beta_scale_ * mismatch * mismatch / alpha; }
  double force_overlap_ = 0.0, force_cubic_ = 0.0, force_rate_ = 0.0;  // coefficients of evaluate()
  double overlap_radius_ = 0.0, beta_scale_ = 0.0;
  double crack_ = 0.0, crack_energy_ = 0.0, bulk_energy_ = 0.0;

 public:
  /// The events, by index.
  enum Event : int {
    max_compression,  ///< delta' = 0
    breaks,           ///< beta reaches (1 - margin)/k: the crack runs away, the contact breaks
    sticks,           ///< the mechanical energy below what a separation needs: sticking is certain
    phase_change,     ///< time -> closing, closing or opening -> time
    enters_opening,   ///< time -> opening
    time_limit,       ///< the time budget (or the end of a followed collision)
    event_count_,
  };
  int event_count() const override { return event_count_; }
  void events(double t, const double* y, double* g) const override {
    const Physical x = physical(y);
    events(t, y, x, phase_ == Phase::closing ? 0.0 : models::crack_speed_function(x.beta, p_.k).value, g);
  }
  // The events from the state's beta and crack law f(beta) (unused in the closing phase).
  void events(double t, const double* y, const Physical& x, double crack_law, double* g) const {
    g[max_compression] = y[1];
    g[breaks] = beta_break_ - x.beta;
    g[sticks] = stick_event_ ? mechanical_energy(y) - sticking_threshold(x) : 1.0;
    switch (phase_) {
      case Phase::time:
        g[phase_change] = x.beta - closing_entry;
        g[enters_opening] = std::min(opening_entry - x.beta, relative_crack_rate(x, crack_law) + collapse_entry);
        break;
      case Phase::closing:
        g[phase_change] = closing_exit - x.beta;
        g[enters_opening] = 1.0;
        break;
      case Phase::opening:
        g[phase_change] = std::max(x.beta - opening_exit, -(relative_crack_rate(x, crack_law) + collapse_exit));
        g[enters_opening] = 1.0;
        break;
    }
    g[time_limit] = time_limit_ - t;
  }
  void set_phase(Phase phase) { phase_ = phase; }
  void set_time_limit(double t) { time_limit_ = t; }

  // a'/a per scaled time unit (positive: the contact grows).
  double relative_crack_rate(const Physical& x, double crack_law) const { return c_ * crack_law / x.a * s_.time; }

  // The energy below which the grains can never separate [scaled]. U_K + U_E + U_S
  // never increases and equals U_K >= 0 after a separation, so 0 always (docs/decisions.md D10).
  // Sharper, from the sign structure of the crack law (a' > 0 iff beta < 1): while
  // delta >= delta_c (the JKR fold) a contact with a >= a_c cannot shrink below a_c
  // (at a = a_c, beta <= 1), and a break needs delta < delta_c; crossing delta_c with
  // a >= a_c costs U(a, delta_c) >= U(a_c, delta_c) > 0, the energy at the fold
  // (U increases with a where beta > 1). So with delta >= delta_c and a >= a_c the
  // grains stick once U_K + U_E + U_S < U(a_c, delta_c) (docs/adhesive.md). Without it
  // a weakly damped bound pair oscillated for millions of steps before reaching 0.
  double sticking_threshold(const Physical& x) const {
    return x.delta >= fold_overlap_ && x.a >= fold_radius_ ? fold_energy_ : 0.0;
  }

  // (U_K + U_E + U_S) / (m g^2 / 2)
  double mechanical_energy(const double* y) const {
    const Physical x = physical(y);
    return y[1] * y[1] + models::contact_energy(p_, x.a, x.delta) / s_.energy;
  }

 private:
  models::KrijtParameters p_;
  Scales s_;
  double c_;
  double beta_break_;
  bool stick_event_;
  double fold_overlap_, fold_radius_, fold_energy_;  // JKR fold delta_c, a_c, U(a_c, delta_c) [scaled]
  Phase phase_ = Phase::time;
  double time_limit_ = 0.0;
};

}  // namespace bounce::dynamics::detail

#include "bounce/dynamics/tangential.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

// Boost 1.74's pchip.hpp calls isnan unqualified; it must be visible where the header
// is read (fixed in later Boost releases).
using std::isnan;
#include <boost/math/interpolators/pchip.hpp>
#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "event_integrator.hpp"
#include "normal_system.hpp"

namespace bounce::dynamics {

using models::AsperityForm;
using models::EndRule;
using models::TangentialLaw;
using models::TangentialModel;

namespace {

enum class Mode { resolved, averaged };

// Largest relative change of the sliding speed over one sawtooth period for which the
// sawtooth is averaged (the averaging error is of second order in it).
constexpr double dense_change = 1e-3;

// The tangential motion in scaled units: z' = zeta'/g^T, time unit t_u, normal force
// f = F^N t_u / (m g^N); energies in units of (1/2) m kappa (g^T)^2. The spring state q is
// the extension (zeta - zeta_a)/zeta0 (published form) or w = u / (sqrt(m kappa) g^T)
// with E_s = u^2/2 (passive form).
struct TangentialScaled {
  TangentialModel m;
  double ratio = 1.0;     // g^N / g^T
  double lambda_t = 0.0;  // g^T t_u / zeta0: asperity lengths slid per time unit at speed g^T
  double lambda_n = 0.0;  // g^N t_u / zeta0
  double gamma_t = 0.0;   // gamma_s t_u
  Mode mode = Mode::resolved;

  // Asperity breaks per time unit while sliding at z'.
  double breaks_per_time(double zp) const { return lambda_t * std::abs(zp); }
  // Relative change of the sliding speed over one sawtooth period (mean force).
  double change_per_period(double f, double zp) const {
    return 0.5 * m.friction * std::max(f, 0.0) * ratio / (m.kappa * lambda_t * zp * zp);
  }
  bool averaging_holds(double f, double zp) const {
    return breaks_per_time(zp) > m.dense_breaks && change_per_period(f, zp) < dense_change;
  }
  // Angular frequency of the asperity spring, sqrt(k / (m kappa)) t_u, k = mu F^N / zeta0.
  double omega(double f) const { return std::sqrt(m.friction * std::max(f, 0.0) * lambda_n / m.kappa); }

  // d/dt of (z', q, D), D the dissipated energy. BSHP96 (10) with (35), (39).
  void operator()(double f, double zp, double q, double& dzp, double& dq, double& dd) const {
    f = std::max(f, 0.0);  // no shear in tension
    dq = 0.0;
    if (m.law == TangentialLaw::step) {  // (39)
      const double magnitude = std::min(gamma_t * std::abs(zp), m.friction * f * ratio) / m.kappa;
      dzp = -std::copysign(magnitude, zp);
      dd = -2.0 * zp * dzp;
      return;
    }
    if (mode == Mode::averaged) {  // the sawtooth's mean: sliding at mu F^N / 2
      dzp = -std::copysign(0.5 * m.friction * f * ratio / m.kappa, zp);
      dq = lambda_t * zp;  // q: the slip in asperity lengths, whose fraction is the phase
      dd = -2.0 * zp * dzp;
      return;
    }
    dd = 0.0;
    if (m.form == AsperityForm::published) {  // (35) with the anchor: F^T = -mu F^N q
      dzp = -m.friction * f * ratio * q / m.kappa;
      dq = lambda_t * zp;
    } else {  // F^T = sqrt(k) u, u' = -sqrt(k) zeta': a rotation of (z', w) at rate omega
      const double w = omega(f);
      dzp = w * q;
      dq = -w * zp;
    }
  }
  // Energy stored in the asperity spring (scaled).
  double stored(double f, double q) const {
    if (m.law == TangentialLaw::step || mode == Mode::averaged) return 0.0;
    if (m.form == AsperityForm::published) {
      const double w = omega(f) / lambda_t;
      return w * w * q * q;
    }
    return q * q;
  }
  // > 0 while the asperity holds; 0 where |F^T| = mu F^N (it breaks).
  double hold(double f, double q) const {
    return m.form == AsperityForm::published ? 1.0 - std::abs(q) : omega(f) / lambda_t - std::abs(q);
  }
};

// Bookkeeping of one oblique collision across the restarts at breaks and mode changes.
struct TangentialRun {
  TangentialScaled c;
  double zp = 1.0, q = 0.0, d = 0.0;
  long breaks = 0;
  double averaged_time = 0.0;  // scaled
  bool asperity() const { return c.m.law == TangentialLaw::asperity; }
  // A break: the stored energy is lost, a fresh asperity takes over.
  void on_break(double f) {
    d += c.stored(f, q);
    q = 0.0;
    ++breaks;
  }
  // Into averaged mode q becomes the slip since the anchor in asperity lengths; out of
  // it the sawtooth resumes at the phase phi that slip gives. Over whole periods the mean
  // force gives the sawtooth's impulse; over the partial periods at either end it does
  // not, by mu F^N zeta0 phi (1 - phi) / (2 v): z' is corrected by that impulse on entry
  // and exit (at constant speed over the partial period; what remains is second order).
  void switch_mode(double f) {
    const double omega_ratio = c.omega(f) / c.lambda_t;  // |w| at the Coulomb limit (passive form)
    auto partial_period = [&](double phi) {
      return std::copysign(c.m.friction * std::max(f, 0.0) * c.ratio * phi * (1.0 - phi) /
                               (2.0 * c.m.kappa * c.lambda_t * std::abs(zp)),
                           zp);
    };
    if (c.mode == Mode::resolved) {
      if (c.m.form == AsperityForm::passive) q = omega_ratio > 0.0 ? -q / omega_ratio : 0.0;
      zp -= partial_period(std::abs(q));  // the averaged remainder of this period decelerates more
      c.mode = Mode::averaged;
    } else {
      const double phase = std::fmod(q, 1.0);
      zp += partial_period(std::abs(phase));
      q = c.m.form == AsperityForm::published ? phase : -phase * omega_ratio;
      c.mode = Mode::resolved;
    }
  }
  TangentialOutcome outcome(double f_end, double energy, double time_unit, long steps) const {
    TangentialOutcome t;
    t.cor = zp;
    t.initial_kinetic = energy;
    t.final_kinetic = energy * zp * zp;
    t.asperity_dissipated = energy * d;
    t.stored_at_end = energy * c.stored(f_end, q);
    t.stiffness_work = t.final_kinetic + t.asperity_dissipated + t.stored_at_end - energy;
    t.breaks = breaks;
    t.averaged_time = averaged_time * time_unit;
    t.steps = steps;
    return t;
  }
};

// A run of the tangential motion: time unit t_u, the normal speed over the tangential one,
// and the normal length that sets the spring's stiffness (xi0, or g^N t_u for a recording).
TangentialRun start_run(const TangentialModel& tangential, double normal_speed, double tangential_speed,
                        double time_unit, double normal_length, double f0) {
  TangentialRun run;
  run.c.m = tangential;
  run.c.ratio = normal_speed / tangential_speed;
  if (tangential.law == TangentialLaw::asperity) {
    run.c.lambda_t = tangential_speed * time_unit / tangential.asperity_size;
    run.c.lambda_n = normal_length / tangential.asperity_size;
  }
  run.c.gamma_t = tangential.shear_damping * time_unit;
  if (run.asperity() && run.c.averaging_holds(f0, 1.0)) run.c.mode = Mode::averaged;  // dense from the start
  return run;
}

using detail::CollisionEvent;

// The asperity's break and the change of mode on the tangential components starting at
// `at` (z' = y[at], q = y[at + 1]); `force` gives the scaled normal force of a state.
template <std::size_t N, class Force>
void add_tangential_events(std::vector<detail::Event<N>>& events, const TangentialScaled& c, std::size_t at,
                           Force force) {
  const bool asperity = c.m.law == TangentialLaw::asperity;
  auto hold = detail::make_event<N>(
      CollisionEvent::asperity_break,
      [c, at, force](double t, const detail::State<N>& y) { return c.hold(force(t, y), y[at + 1]); }, true,
      asperity && c.mode == Mode::resolved);
  hold.graze = true;  // an asperity loaded just up to mu F^N at the top of its load breaks
  auto mode = detail::make_event<N>(
      CollisionEvent::mode_change,
      [c, at, force](double t, const detail::State<N>& y) {
        const double rate = c.breaks_per_time(y[at]);
        const double change = c.change_per_period(force(t, y), y[at]);
        // Averaged while sliding fast (rate) and steadily (change); hysteresis, a factor 10
        // on both, so that the mode cannot chatter.
        return c.mode == Mode::resolved ? std::max(c.m.dense_breaks - rate, change - dense_change)
                                        : std::min(rate - 0.1 * c.m.dense_breaks, 10.0 * dense_change - change);
      },
      true, asperity);
  events.push_back(hold);
  events.push_back(mode);
}

// After an asperity event the run restarts from the state the break or mode change leaves.
bool restarts(int id) { return id == detail::id(CollisionEvent::asperity_break) || id == detail::id(CollisionEvent::mode_change); }

// Normal and tangential motion integrated together (BSHP96 (10) beside (13)), in the scaled
// units of the normal collision: x, v, normal dissipation, z', q, D.
class Oblique {
 public:
  using State = detail::State<6>;

  Oblique(const models::NormalForceModel& model, double mass, double gn, double gt, const TangentialModel& tangential,
          const NormalCollisionOptions& options)
      : model_(model), options_(options), gn_(gn), xi0_(model.reference_overlap(gn)), time_unit_(xi0_ / gn),
        energy_unit_(mass * gn * gn), normal_{&model, xi0_, gn, xi0_ / energy_unit_},
        cutoff_(model.cutoff_overlap(gn) / xi0_), run_(start_run(tangential, gn, gt, time_unit_, xi0_, 0.0)),
        y_{cutoff_, 1.0, 0.0, 1.0, 0.0, 0.0},
        tangential_energy_(0.5 * mass * tangential.kappa * gt * gt) {}

  TangentialCollision run() {
    while (segment()) {
    }
    TangentialCollision out;
    out.normal.method = "integrate";
    out.normal.steps = steps_;
    detail::finish_normal_outcome(out.normal, end_, model_, xi0_, time_unit_, energy_unit_);
    out.tangential = run_.outcome(force(0.0, y_), tangential_energy_, time_unit_, steps_);
    return out;
  }

 private:
  double force(double, const State& s) const { return model_.force(xi0_ * s[0], gn_ * s[1]) * xi0_ / energy_unit_; }

  // A restart exactly where the contact ends would miss its event (the end function
  // starts on its far side): the contact has ended if the state says so.
  bool over() const {
    if (!end_.compressed) return false;
    if (options_.end_rule == EndRule::overlap) return y_[0] <= cutoff_;
    return y_[0] <= 0.0 || model_.force_sign(xi0_ * y_[0], gn_ * y_[1]) <= 0.0;
  }

  std::vector<detail::Event<6>> events(const TangentialScaled& c) const {
    auto e = detail::normal_events<6>(model_, options_.end_rule, cutoff_, xi0_, gn_, energy_unit_);
    if (end_.compressed) {  // resumed after the maximum compression
      e[detail::id(CollisionEvent::max_compression)].armed = false;
      e[detail::id(CollisionEvent::end_of_contact)].armed = true;
    }
    add_tangential_events<6>(e, c, 3, [this](double t, const State& s) { return force(t, s); });
    return e;
  }

  // Integrates to the next event; true when the run goes on (an asperity broke or the
  // mode changed inside the contact).
  bool segment() {
    const TangentialScaled c = run_.c;
    auto system = [this, c](const State& s, State& dsdt, double) {
      const double f = normal_(s, dsdt);
      c(f, s[3], s[4], dsdt[3], dsdt[4], dsdt[5]);
    };
    std::vector<detail::Event<6>> e = events(c);
    IntegrationSettings settings = options_.integration;
    settings.max_steps = options_.integration.max_steps - steps_;
    const double step = 1e-3 / std::max(1.0, c.lambda_t * std::abs(y_[3]));
    const auto result = detail::integrate_until_event<6>(system, y_, t_, step, settings, e);
    steps_ += result.steps;
    if (c.mode == Mode::averaged) run_.averaged_time += result.terminal.time - t_;
    for (const auto& hit : result.hits) {
      if (hit.id == detail::id(CollisionEvent::max_compression)) {
        end_.compressed = true;
        end_.max_overlap = hit.state[0];
        end_.max_overlap_time = hit.time;
      }
    }
    y_ = result.terminal.state;
    t_ = result.terminal.time;
    run_.zp = y_[3];
    run_.q = y_[4];
    run_.d = y_[5];
    const int id = result.terminal.id;
    if (restarts(id) && !over()) {
      const double f = force(t_, y_);
      id == detail::id(CollisionEvent::asperity_break) ? run_.on_break(f) : run_.switch_mode(f);
      y_[3] = run_.zp;
      y_[4] = run_.q;
      y_[5] = run_.d;
      return true;
    }
    end_.time = t_;
    end_.x = y_[0];
    end_.v = y_[1];
    end_.dissipated = y_[2];
    end_.stuck = id == detail::id(CollisionEvent::sticks);
    return false;
  }

  const models::NormalForceModel& model_;
  const NormalCollisionOptions& options_;
  double gn_, xi0_, time_unit_, energy_unit_;
  detail::NormalScaled normal_;
  double cutoff_;
  TangentialRun run_;
  State y_;
  double t_ = 0.0;
  double tangential_energy_;
  detail::NormalEnd end_;
  long steps_ = 0;
};

// The normal force of a finished collision: samples, monotone cubic interpolation between
// them, in scaled units (time unit a third of the contact, speed the impact's).
struct RecordedForce {
  double time_unit = 0.0, normal_speed = 0.0, tau_end = 0.0;
  std::optional<boost::math::interpolators::pchip<std::vector<double>>> force;

  RecordedForce(const std::vector<TrajectorySample>& normal, double mass) {
    if (normal.size() < 4) throw NumericalError("the normal trajectory has fewer than 4 samples");
    const double t0 = normal.front().time, t_end = normal.back().time;
    time_unit = (t_end - t0) / 3.0;
    normal_speed = std::abs(normal.front().rate);
    if (!(time_unit > 0.0 && normal_speed > 0.0)) throw NumericalError("the normal trajectory is degenerate");
    std::vector<double> times, forces;
    for (const auto& s : normal) {
      const double tau = (s.time - t0) / time_unit;
      if (!times.empty() && tau <= times.back()) continue;  // samples at an event can repeat a time
      times.push_back(tau);
      forces.push_back((s.elastic_force + s.dissipative_force) * time_unit / (mass * normal_speed));
    }
    tau_end = times.back();
    force.emplace(std::move(times), std::move(forces));
  }
  double operator()(double tau) const { return (*force)(std::clamp(tau, 0.0, tau_end)); }
};

}  // namespace

TangentialCollision integrate_tangential_collision(const models::NormalForceModel& model, double effective_mass,
                                                   double normal_speed, double tangential_speed,
                                                   const TangentialModel& tangential,
                                                   const NormalCollisionOptions& options) {
  return Oblique(model, effective_mass, normal_speed, tangential_speed, tangential, options).run();
}

TangentialOutcome integrate_tangential_motion(const std::vector<TrajectorySample>& normal, double effective_mass,
                                              double tangential_speed, const TangentialModel& tangential,
                                              const IntegrationSettings& settings) {
  const RecordedForce f(normal, effective_mass);
  TangentialRun run = start_run(tangential, f.normal_speed, tangential_speed, f.time_unit,
                                f.normal_speed * f.time_unit, f(0.0));
  using State = detail::State<3>;  // z', q, D
  State y{1.0, 0.0, 0.0};
  double t = 0.0;
  long steps = 0;
  for (;;) {
    const TangentialScaled c = run.c;
    auto system = [c, &f](const State& s, State& dsdt, double tau) { c(f(tau), s[0], s[1], dsdt[0], dsdt[1], dsdt[2]); };
    const double tau_end = f.tau_end;
    std::vector<detail::Event<3>> events = {detail::make_event<3>(
        CollisionEvent::end_of_record, [tau_end](double tau, const State&) { return tau_end - tau; }, true, true)};
    add_tangential_events<3>(events, c, 0, [&f](double tau, const State&) { return f(tau); });
    IntegrationSettings s = settings;
    s.max_steps = settings.max_steps - steps;
    s.max_time = 2.0 * tau_end;
    const auto result = detail::integrate_until_event<3>(system, y, t, 1e-3 / std::max(1.0, c.lambda_t * std::abs(y[0])),
                                                         s, events);
    steps += result.steps;
    if (c.mode == Mode::averaged) run.averaged_time += result.terminal.time - t;
    y = result.terminal.state;
    t = result.terminal.time;
    run.zp = y[0];
    run.q = y[1];
    run.d = y[2];
    if (!restarts(result.terminal.id) || t >= tau_end) break;
    result.terminal.id == detail::id(CollisionEvent::asperity_break) ? run.on_break(f(t)) : run.switch_mode(f(t));
    y = {run.zp, run.q, run.d};
  }
  const double tangential_energy = 0.5 * effective_mass * tangential.kappa * tangential_speed * tangential_speed;
  return run.outcome(f(f.tau_end), tangential_energy, f.time_unit, steps);
}

}  // namespace bounce::dynamics

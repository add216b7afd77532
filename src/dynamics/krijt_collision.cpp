// K13's dynamic model (`krijt`): delta, delta', a and the two dissipations integrated by
// the stiff engine, in phases (the contact radius as the independent variable where the
// crack runs, krijt_system.hpp), over one or more contact episodes.
#include <algorithm>
#include <cmath>
#include <memory>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

#include "adhesive_outcome.hpp"
#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/core/error.hpp"
#include "bounce/dynamics/adhesive_collision.hpp"
#include "krijt_system.hpp"
#include "stiff.hpp"

namespace bounce::dynamics {

namespace {

using detail::KrijtSystem;
using detail::Phase;
using detail::Scales;

constexpr int a_index = 2;  // the contact radius in the state (delta, delta', a, U_CD, U_BD)

// 2 pi a_eq^2 gamma / ((1/2) m g^2): the adhesion energy in units of the impact energy.
double adhesion_energy_ratio(const models::KrijtParameters& p, const Scales& s) {
  const contact::jkr::Parameters j{p.effective_radius, p.effective_modulus, p.surface_energy};
  const double a = contact::jkr::equilibrium_contact_radius(j);
  return 2.0 * detail::pi * a * a * p.surface_energy / s.energy;
}

TrajectorySample krijt_sample(const models::KrijtParameters& p, const Scales& s, double t, const std::vector<double>& y) {
  TrajectorySample out;
  out.time = t * s.time;
  out.overlap = y[0] * s.length;
  out.rate = y[1] * s.speed;
  out.contact_radius = y[2] * s.radius;
  out.elastic_force = models::elastic_force(p, out.contact_radius, out.overlap);
  out.dissipative_force = models::bulk_dissipative_force(p, out.contact_radius, out.rate);
  out.effective_surface_energy_ratio = models::effective_surface_energy_ratio(p, out.contact_radius, out.overlap);
  out.kinetic = 0.5 * p.effective_mass * out.rate * out.rate;
  out.elastic =
      contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, out.contact_radius, out.overlap);
  out.surface = contact::independent::surface_energy(out.contact_radius, p.surface_energy);
  out.crack_dissipated = y[3] * s.energy;
  out.bulk_dissipated = y[4] * s.energy;
  return out;
}

// One contact episode: from first touch (delta = 0, speed g) to the run-away of the
// crack or sticking. `approaching` reports a break with delta' > 0 (the grains were
// pulled back by the adhesive neck when it ruptured: they will meet again).
struct Episode {
  CollisionOutcome outcome;
  double final_overlap = 0.0;  // delta at the break [m]
  double final_rate = 0.0;     // delta' at the break [m/s]
  bool approaching = false;
};

class KrijtEpisode {
 public:
  KrijtEpisode(const models::KrijtParameters& p, double speed, const AdhesiveCollisionOptions& options);
  Episode run();

 private:
  void run_phase();
  void take_step(detail::StiffIntegrator& integrator, const detail::SwappedIndependent& swapped, Phase& next);
  void on_event(int event, detail::StiffIntegrator& integrator, Phase& next);
  void end_of_follow();
  void record(const detail::StiffIntegrator& integrator, const detail::SwappedIndependent& swapped, double t_before,
              const detail::StiffIntegrator::Step& step);
  std::vector<double> state_at_time(const detail::StiffIntegrator& integrator,
                                    const detail::SwappedIndependent& swapped, double when, double s_lo,
                                    double s_hi) const;
  Episode finish();

  const models::KrijtParameters& p_;
  const AdhesiveCollisionOptions& options_;
  const Scales s_;
  const models::InitialContact start_;
  const bool follow_;      // the user asked to follow the collision to a time
  bool following_;         // ... and that time has not come yet
  KrijtSystem system_;
  detail::StiffSettings settings_;
  double t_hertz_ = 0.0;  // K13 (22), scaled
  double time_limit_ = 0.0, spacing_ = 0.0, next_sample_ = 0.0;
  CollisionOutcome out_;
  TrajectoryRecorder trajectory_{out_.trajectory, out_.trajectory_thinning};
  std::vector<double> y_;
  double t_ = 0.0;
  long steps_ = 0;
  bool compressed_ = false;  // the maximum compression was passed
  bool ended_ = false;
  bool broke_ = false;          // the contact broke off (the only way a collision bounces)
  bool stick_certain_ = false;  // the energy fell below what a separation needs
  bool restart_ = false;        // the time limit moved: the phase restarts with a new budget
  Phase phase_ = Phase::time;
};

KrijtEpisode::KrijtEpisode(const models::KrijtParameters& p, double speed, const AdhesiveCollisionOptions& options)
    : p_(p), options_(options), s_(detail::scales_for(p, speed)), start_(models::krijt_initial_contact(p)),
      follow_(options.follow_time > 0.0), following_(follow_), system_(p, s_, true, options.break_margin) {
  y_ = {0.0, 1.0, start_.contact_radius / s_.radius, start_.crack_dissipated / s_.energy, 0.0};
  t_hertz_ = detail::scaled_hertz_time(p, speed, s_);
  t_ = start_.time / s_.time;
  time_limit_ = follow_ ? options.follow_time / s_.time : 1e4 * t_hertz_;
  system_.set_time_limit(time_limit_);
  // The energies exchanged reach the adhesion energy 2 pi a_eq^2 gamma, which can exceed
  // the impact energy (the unit) by orders of magnitude in slow collisions: a relative
  // error tol in a then costs tol * 2 pi a_eq^2 gamma / E0 in the energy budget. The
  // tolerance is tightened by that ratio so that the budget closes to ~tol of E0.
  const double tolerance = options.relative_tolerance * std::min(1.0, 1.0 / adhesion_energy_ratio(p, s_));
  settings_.relative_tolerance = tolerance;
  settings_.absolute_tolerance.assign(5, tolerance * 1e-2);
  settings_.event_directions.assign(KrijtSystem::event_count_, -1);
  out_.method = "integrate";
  spacing_ = 2.0 * t_hertz_ / std::max(options.trajectory_points, 1);
  next_sample_ = t_;
  if (options.record_trajectory) trajectory_.add(krijt_sample(p, s_, t_, y_));
  // Bound from the start: the formation already took more than the kinetic energy.
  stick_certain_ = system_.mechanical_energy(y_.data()) <= 0.0;
  ended_ = !following_ && stick_certain_;
  if (ended_) out_.outcome = Outcome::stick;
  phase_ = system_.physical(y_.data()).beta < detail::closing_exit ? Phase::closing : Phase::time;
}

// The state at time `when` inside the last step [s_lo, s_hi] (the time is monotone in s in
// every phase; in the a phases the state holds t in place of a).
std::vector<double> KrijtEpisode::state_at_time(const detail::StiffIntegrator& integrator,
                                                const detail::SwappedIndependent& swapped, double when, double s_lo,
                                                double s_hi) const {
  if (phase_ == Phase::time) return integrator.state_at(when);
  auto gap = [&](double x) { return integrator.state_at(x)[a_index] - when; };
  boost::uintmax_t iterations = 60;
  const auto root =
      boost::math::tools::toms748_solve(gap, s_lo, s_hi, boost::math::tools::eps_tolerance<double>(50), iterations);
  const double x = 0.5 * (root.first + root.second);
  return swapped.original(x, integrator.state_at(x).data());
}

void KrijtEpisode::record(const detail::StiffIntegrator& integrator, const detail::SwappedIndependent& swapped,
                          double t_before, const detail::StiffIntegrator::Step& step) {
  for (; next_sample_ < t_; next_sample_ += trajectory_.step(spacing_, s_.time)) {
    if (next_sample_ > t_before) {
      trajectory_.add(
          krijt_sample(p_, s_, next_sample_, state_at_time(integrator, swapped, next_sample_, step.t0, step.t1)));
    }
  }
  trajectory_.add(krijt_sample(p_, s_, t_, y_));
}

void KrijtEpisode::on_event(int event, detail::StiffIntegrator& integrator, Phase& next) {
  switch (event) {
    case KrijtSystem::max_compression:
      out_.max_overlap = y_[0] * s_.length;
      out_.time_of_max_overlap = t_ * s_.time;
      compressed_ = true;
      integrator.disable_event(KrijtSystem::max_compression);
      break;
    case KrijtSystem::breaks:
      out_.outcome = Outcome::bounce;
      broke_ = true;
      ended_ = true;
      break;
    case KrijtSystem::sticks:  // followed: on to the end time, then stick
      stick_certain_ = true;
      if (!following_) {
        out_.outcome = Outcome::stick;
        ended_ = true;
      }
      break;
    case KrijtSystem::phase_change:
    case KrijtSystem::enters_opening:
      next = phase_ != Phase::time                   ? Phase::time
             : event == KrijtSystem::phase_change ? Phase::closing
                                                     : Phase::opening;
      break;
    case KrijtSystem::time_limit:
      if (!following_) {
        throw TimeBudgetExceeded(fmt::format("the K13 collision lasted more than {:.3g} s without an outcome", t_ * s_.time));
      }
      end_of_follow();
      break;
  }
}

// The followed time has come. With sticking certain the run ends (stick); otherwise the
// outcome is still open (a time shorter than the collision), and the run goes on as an
// unfollowed one until the contact breaks or sticking is certain, with a fresh budget.
void KrijtEpisode::end_of_follow() {
  following_ = false;
  if (stick_certain_) {
    out_.outcome = Outcome::stick;
    ended_ = true;
    return;
  }
  time_limit_ = t_ + 1e4 * t_hertz_;
  system_.set_time_limit(time_limit_);
  restart_ = true;
}

// One step, its samples and its events.
void KrijtEpisode::take_step(detail::StiffIntegrator& integrator, const detail::SwappedIndependent& swapped,
                             Phase& next) {
  const detail::StiffIntegrator::Step step = integrator.step();
  const std::vector<double> z = integrator.state();
  const double t_before = t_;
  if (phase_ == Phase::time) {
    y_ = z;
    t_ = step.t1;
  } else {
    y_ = swapped.original(step.t1, z.data());
    t_ = z[a_index];
  }
  if (options_.record_trajectory) record(integrator, swapped, t_before, step);
  for (int event : step.fired) on_event(event, integrator, next);
}

// The integration in the current phase until the phase changes or the episode ends.
void KrijtEpisode::run_phase() {
  system_.set_phase(phase_);
  const double sign = phase_ == Phase::opening ? -1.0 : 1.0;  // in the a phases s = +-a increases
  const detail::SwappedIndependent swapped(system_, a_index, sign);
  const detail::StiffSystem& equations =
      phase_ == Phase::time ? static_cast<const detail::StiffSystem&>(system_) : swapped;
  std::vector<double> z = y_;
  double s0 = t_;
  // A followed run ends at its time_limit event (with the state there); the engine's own
  // budget lies beyond it, or a step that lands on the event would throw before the event
  // is handled and leave the state one step short. Unfollowed, both mean the same failure,
  // and the budget stays where it was (CVODE's first step depends on it).
  settings_.max_time = following_ ? 2.0 * time_limit_ : time_limit_;
  if (phase_ != Phase::time) {
    z[a_index] = t_;
    s0 = sign * y_[a_index];
    settings_.max_time = phase_ == Phase::opening ? 0.0 : 1e6;  // a = 0; a bound never reached
  }
  settings_.max_steps = options_.max_steps - steps_;
  const auto integrator = detail::make_stiff_integrator(options_.engine, equations, z, s0, settings_);
  if (compressed_) integrator->disable_event(KrijtSystem::max_compression);
  Phase next = phase_;
  restart_ = false;
  while (!ended_ && !restart_ && next == phase_) take_step(*integrator, swapped, next);
  steps_ += integrator->steps();
  phase_ = next;
}

Episode KrijtEpisode::finish() {
  if (options_.record_trajectory && out_.trajectory.back().time < t_ * s_.time) {  // a thinned trajectory's end
    trajectory_.add_end(krijt_sample(p_, s_, t_, y_));
  }
  if (!compressed_ && out_.outcome == Outcome::stick) {  // stopped while still compressing
    out_.max_overlap = std::max(y_[0], 0.0) * s_.length;
    out_.time_of_max_overlap = t_ * s_.time;
    out_.compression_unfinished = true;
    out_.notes.push_back(detail::before_max_compression_note);
  }
  // A followed collision that never broke off is a sticking one, also when it reached its
  // end time still in contact (the outcome's default is no answer there).
  if (follow_ && !broke_) out_.notes.push_back(detail::followed_note(options_.follow_time, t_ * s_.time));
  Episode episode;
  episode.final_overlap = y_[0] * s_.length;
  episode.final_rate = y_[1] * s_.speed;
  episode.approaching = out_.outcome == Outcome::bounce && y_[1] > 0.0;
  out_.steps = steps_;
  out_.contact_time = t_ * s_.time;
  out_.energy.bulk_dissipated = y_[4] * s_.energy;
  out_.energy.crack_dissipated = y_[3] * s_.energy;
  const double a = y_[2] * s_.radius, delta = y_[0] * s_.length;
  const contact::independent::Geometry g{p_.effective_radius, p_.effective_modulus};
  detail::finish_adhesive(out_, s_, y_[1], contact::independent::elastic_energy(g, a, delta),
                          contact::independent::surface_energy(a, p_.surface_energy), out_.outcome == Outcome::bounce);
  episode.outcome = std::move(out_);
  return episode;
}

Episode KrijtEpisode::run() {
  while (!ended_) run_phase();
  return finish();
}

// The second episode's record joins the first: shifted in time, on top of the energies
// already dissipated.
void append_episode(CollisionOutcome& out, const CollisionOutcome& n, double shift, double rate, double speed) {
  for (TrajectorySample sample : n.trajectory) {
    sample.time += shift;
    sample.bulk_dissipated += out.energy.bulk_dissipated;
    sample.crack_dissipated += out.energy.crack_dissipated;
    out.trajectory.push_back(sample);
  }
  out.trajectory_thinning = std::max(out.trajectory_thinning, n.trajectory_thinning);
  out.outcome = n.outcome;
  out.cor = n.cor * rate / speed;  // rebound speed relative to the first impact speed
  out.contact_time = shift + n.contact_time;
  if (n.compression_unfinished && n.max_overlap > out.max_overlap) out.compression_unfinished = true;
  out.max_overlap = std::max(out.max_overlap, n.max_overlap);
  out.steps += n.steps;
  out.energy.bulk_dissipated += n.energy.bulk_dissipated;
  out.energy.crack_dissipated += n.energy.crack_dissipated;
  out.energy.final_kinetic = n.energy.final_kinetic;
  out.energy.elastic_remaining = n.energy.elastic_remaining;
  out.energy.surface_remaining = n.energy.surface_remaining;
  out.notes.insert(out.notes.end(), n.notes.begin(), n.notes.end());
}

// A break while approaching (delta < 0 there: the surfaces are apart): free flight to
// delta = 0, then a new contact with K13's initial condition at that speed.
CollisionOutcome krijt_collision(const models::KrijtParameters& p, double speed, const AdhesiveCollisionOptions& options) {
  Episode first = KrijtEpisode(p, speed, options).run();
  CollisionOutcome out = std::move(first.outcome);
  double rate = first.final_rate, overlap = first.final_overlap;
  for (int episodes = 1; first.approaching; ++episodes) {
    if (episodes >= 100) throw NumericalError("more than 100 contact episodes in one encounter");
    if (overlap > 0.0) {
      throw NumericalError(
          "the K13 contact broke while the spheres still overlap (crack too slow for K13's initial condition)");
    }
    const double flight = -overlap / rate;
    const double shift = out.contact_time + flight;
    out.notes.push_back(fmt::format(
        "the adhesive neck pulled the grains back and broke while they approached (delta = {:.3g} m, delta' = "
        "{:.3g} m/s at t = {:.3g} s): they met again {:.3g} s later", overlap, rate, out.contact_time, flight));
    const Episode next = KrijtEpisode(p, rate, options).run();
    append_episode(out, next.outcome, shift, rate, speed);
    rate = next.final_rate;
    overlap = next.final_overlap;
    first.approaching = next.approaching;
  }
  out.energy.close();
  return out;
}

}  // namespace

CollisionOutcome integrate_krijt_collision(const models::KrijtParameters& p, double speed,
                                           const AdhesiveCollisionOptions& options) {
  if (options.engine != StiffEngine::rodas) return krijt_collision(p, speed, options);
  try {
    return krijt_collision(p, speed, options);
  } catch (const StepBudgetExceeded&) {
    throw;
  } catch (const TimeBudgetExceeded&) {
    throw;
  } catch (const NumericalError& e) {
    // RODAS can stall where a crack ~1e12 times faster than the collision meets the
    // non-smooth part of the crack law (1 run in the 87 516 of the robustness grid);
    // BDF does not. The whole collision is recomputed with CVODE.
    AdhesiveCollisionOptions cvode = options;
    cvode.engine = StiffEngine::cvode;
    try {
      CollisionOutcome out = krijt_collision(p, speed, cvode);
      out.notes.push_back(fmt::format("computed with CVODE: RODAS stopped ({})", e.what()));
      return out;
    } catch (const NumericalError& second) {  // both engines failed: say so, first the one asked for
      throw NumericalError(fmt::format("RODAS stopped ({}); CVODE, tried next, too ({})", e.what(), second.what()));
    }
  }
}

}  // namespace bounce::dynamics

// A contact held on its adhesive equilibrium branch (models/adhesive_geometry.hpp: JKR for
// jkr-viscoelastic and krijt's fast-crack limit, Maugis-Dugdale for maugis-viscoelastic) plus the
// bulk force K13 (19). Not stiff: integrated with dopri5 (event_integrator.hpp).
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "adhesive_outcome.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/dynamics/adhesive_collision.hpp"
#include "event_integrator.hpp"
#include "krijt_system.hpp"

namespace bounce::dynamics {

namespace {

using detail::Scales;
using State = detail::State<3>;  // delta / L, rate / g, bulk dissipation / E0

// The events of the collision (their ids).
enum JkrEvent : int { max_compression, release, sticks, end_of_follow, settled };

class AdhesiveContactCollision {
 public:
  AdhesiveContactCollision(const models::AdhesivePair& p, const models::AdhesiveGeometry& geometry, double speed,
                           const AdhesiveCollisionOptions& options);
  CollisionOutcome run();
  // The system: K13 (20) with a and F_E on the branch, and the bulk dissipation K13 (C.3).
  void operator()(const State& y, State& dydt, double) const;

 private:
  // The kinetic energy the pair would have at the release point, in E0, by the energy balance.
  double kinetic_at_release(const State& y) const;
  // The mechanical energy above the branch's least, in E0: what the oscillation still holds.
  double oscillation_energy(const State& y) const;
  State settled_state(const State& y) const;
  [[noreturn]] void refuse_follow(double reached) const;
  std::vector<detail::Event<3>> events(bool following) const;
  detail::IntegrationResult<3> go_on_after_follow(detail::IntegrationResult<3> followed, IntegrationSettings settings,
                                                  const detail::StepObserver<3>* observer) const;
  TrajectorySample sample(double t, const State& y) const;
  detail::IntegrationResult<3> integrate();
  void finish(const detail::IntegrationResult<3>& result);
  void record_end(double t, const State& end, bool bounced, double v);

  const models::AdhesivePair& p_;
  const models::AdhesiveGeometry& geometry_;
  const AdhesiveCollisionOptions& options_;
  const double delta_release_;
  const Scales s_;
  const double delta_snap_, snap_release_, release_energy_, t_hertz_;
  const bool follow_;
  double settle_energy_ = 0.0;  // in E0: below it a followed collision has settled
  CollisionOutcome out_;
  TrajectoryRecorder trajectory_{out_.trajectory, out_.trajectory_thinning};
};

AdhesiveContactCollision::AdhesiveContactCollision(const models::AdhesivePair& p,
                                                   const models::AdhesiveGeometry& geometry, double speed,
                                                   const AdhesiveCollisionOptions& options)
    : p_(p), geometry_(geometry), options_(options), delta_release_(geometry.release_overlap(options.release)),
      s_(detail::scales_for(p, speed, geometry.release_overlap(models::AdhesiveRelease::fold))),
      // Snap-on: the pair jumps onto the branch (JKR: a from 0 to the snap-on radius at delta = 0);
      // -(U_E + U_S) there is released (crack).
      delta_snap_(geometry.snap_overlap()), snap_release_(-geometry.energy(delta_snap_)),
      // Release needs U_E + U_S = U(delta) > 0 at the release point; the mechanical energy
      // never increases, so once it is below that the grains can never separate.
      release_energy_(geometry.energy(delta_release_) / s_.energy),
      t_hertz_(detail::scaled_hertz_time(p, speed, s_)), follow_(options.follow_time > 0.0) {
  out_.method = "integrate";
  // The integration's own resolution of the energy (its tolerance, relative to the larger of E0
  // and |U_least|, integrate() below): an oscillation holding less is settled within it.
  settle_energy_ = options.relative_tolerance * std::max(1.0, -geometry.least_energy() / s_.energy);
}

void AdhesiveContactCollision::operator()(const State& y, State& dydt, double) const {
  const double delta = y[0] * s_.length, rate = y[1] * s_.speed;
  const models::AdhesiveGeometry::State on = geometry_.state(delta);
  const double fd = models::bulk_dissipative_force(p_, on.contact_radius, rate);
  const double force = on.force + fd;
  dydt[0] = y[1];
  dydt[1] = -force / p_.effective_mass * s_.time / s_.speed;  // K13 (20) with a and F_E on the branch
  dydt[2] = fd * rate * s_.time / s_.energy;                  // K13 (C.3)
}

// Along the branch U_K + U(delta) + D = E0 + U(delta_snap) (K13 appendix C: the snap-on's jump
// keeps U_K and releases -U(delta_snap)), so at the release point U_K = E0 - snap_release - U_rel
// - D: the bulk dissipation D (y[2]) alone decides it. It never increases; below 0 the grains
// can never separate. Taken from the balance, not from the integrated rate: where the attraction
// gives the pair far more kinetic energy than the impact brought (a slow impact, a long-range
// Maugis-Dugdale zone: 1e7 x E0), the rate at release is a small difference of large ones and
// loses its digits (e - 1 = 3e-4 without damping at z0 = 1e-6 m, 0.01 m/s), while D keeps its own.
double AdhesiveContactCollision::kinetic_at_release(const State& y) const {
  return 1.0 - snap_release_ / s_.energy - release_energy_ - y[2];
}

double AdhesiveContactCollision::oscillation_energy(const State& y) const {
  return y[1] * y[1] + (geometry_.energy(y[0] * s_.length) - geometry_.least_energy()) / s_.energy;
}

// Settled: at rest at the equilibrium, the oscillation's last energy dissipated (the bulk force
// takes all of it, however long that lasts), so the balance still closes.
State AdhesiveContactCollision::settled_state(const State& y) const {
  return {geometry_.equilibrium_overlap() / s_.length, 0.0, y[2] + oscillation_energy(y)};
}

std::vector<detail::Event<3>> AdhesiveContactCollision::events(bool following) const {
  std::vector<detail::Event<3>> e(3);
  e[0] = {max_compression, [](double, const State& y) { return y[1]; }, -1, false, true, -1};
  e[1] = {release, [this](double, const State& y) { return y[0] - delta_release_ / s_.length; }, -1, true, true, -1};
  e[2] = {sticks, [this](double, const State& y) { return kinetic_at_release(y); }, -1, !following, true, -1};
  if (following) {  // the end of a followed collision, with the state there
    const double end = options_.follow_time / s_.time;
    e.push_back({end_of_follow, [end](double t, const State&) { return end - t; }, -1, true, true, -1});
    // Damped about its equilibrium, a sticking pair settles long before a long followed time
    // (--follow 1e3 s): dopri5 would need ~1e12 steps of the oscillation's period to get there,
    // where krijt's stiff engine strides. Settled within the tolerance, the run ends: the state
    // at the followed time is the equilibrium (issue 40, point 7).
    e.push_back({settled, [this](double, const State& y) { return oscillation_energy(y) - settle_energy_; }, -1, true,
                 true, -1});
  }
  return e;
}

TrajectorySample AdhesiveContactCollision::sample(double t, const State& y) const {
  TrajectorySample x;
  x.time = t * s_.time;
  x.overlap = y[0] * s_.length;
  x.rate = y[1] * s_.speed;
  const models::AdhesiveGeometry::State on = geometry_.state(x.overlap);
  x.contact_radius = on.contact_radius;
  x.elastic_force = on.force;
  x.dissipative_force = models::bulk_dissipative_force(p_, x.contact_radius, x.rate);
  x.effective_surface_energy_ratio = 1.0;
  x.kinetic = 0.5 * p_.effective_mass * x.rate * x.rate;
  x.elastic = geometry_.elastic_energy(x.overlap);
  x.surface = geometry_.surface_energy(x.overlap);
  x.crack_dissipated = snap_release_;
  x.bulk_dissipated = y[2] * s_.energy;
  return x;
}

detail::IntegrationResult<3> AdhesiveContactCollision::integrate() {
  IntegrationSettings settings;
  // The attraction can give the pair far more kinetic energy than the impact brought (a slow
  // impact, a long-range Maugis-Dugdale zone): the tolerance is relative to the impact energy, so
  // the integration's is tightened by |U_least| / E0 where that exceeds 1 (the largest kinetic
  // energy over the impact energy, within a factor 2; continuous, and no change where the impact
  // dominates), down to 1e-14, near dopri5's limit in double precision. The restitution does not
  // depend on it (kinetic_at_release); the trajectory and the closure do.
  const double ratio = std::max(1.0, -geometry_.least_energy() / s_.energy);
  settings.relative_tolerance = settings.absolute_tolerance = std::max(options_.relative_tolerance * 1e-2 / ratio, 1e-14);
  settings.max_steps = options_.max_steps;
  // A followed run ends at its end_of_follow event; the budget lies beyond it.
  settings.max_time = follow_ ? 2.0 * options_.follow_time / s_.time : 1e4 * t_hertz_;
  const double spacing = 2.0 * t_hertz_ / std::max(options_.trajectory_points, 1);
  double next_sample = spacing;  // the start is sampled below
  const detail::StepObserver<3> observer = [&](double t0, double t1, const auto& at) {
    for (; next_sample <= t1; next_sample += trajectory_.step(spacing, s_.time)) {
      if (next_sample >= t0) trajectory_.add(sample(next_sample, at(next_sample)));
    }
  };
  const State start{delta_snap_ / s_.length, 1.0, 0.0};
  if (options_.record_trajectory) trajectory_.add(sample(0.0, start));
  if (!follow_ && kinetic_at_release(start) <= 0.0) {
    detail::IntegrationResult<3> bound;
    bound.terminal = {sticks, 0.0, start};  // bound from the snap-on on
    return bound;
  }
  auto e = events(follow_);
  double reached = 0.0;  // where a followed run got to
  const detail::StepObserver<3> followed = [&](double t0, double t1, const auto& at) {
    reached = t1;
    if (options_.record_trajectory) observer(t0, t1, at);
  };
  const detail::StepObserver<3>* watch = follow_ ? &followed : options_.record_trajectory ? &observer : nullptr;
  detail::IntegrationResult<3> result;
  try {
    result = detail::integrate_until_event<3>(*this, start, 0.0, 1e-4 * t_hertz_, settings, e, watch);
  } catch (const StepBudgetExceeded&) {
    if (follow_) refuse_follow(reached);
    throw;
  }
  if (result.terminal.id == settled) {  // held at the equilibrium until the followed time
    out_.notes.push_back(fmt::format("settled at its equilibrium within the tolerance at {:.6g} s, and held there",
                                     result.terminal.time * s_.time));
    result.terminal = {settled, options_.follow_time / s_.time, settled_state(result.terminal.state)};
  }
  return result.terminal.id == end_of_follow ? go_on_after_follow(std::move(result), settings, watch) : result;
}

// A followed pair that does not settle (A = 0 oscillates for ever; weak damping settles late) needs
// every period of its oscillation up to the followed time: the step budget ends it, and the time
// it reached is the bound the followed time can have.
void AdhesiveContactCollision::refuse_follow(double reached) const {
  throw InvalidArgument("follow", format_value(options_.follow_time),
                        fmt::format("a follow time <= {:.3g} s: there the budget of {} steps ended with the grains' "
                                    "oscillation about their equilibrium (bulk damping A = {:g} s) not yet settled "
                                    "to the tolerance",
                                    reached * s_.time, options_.max_steps, p_.dissipative_constant));
}

// The followed time has come: with sticking certain (the energy below the release energy,
// now or at a `sticks` hit) the run ends there; otherwise the outcome is still open (a time
// shorter than the collision) and the run goes on as an unfollowed one until the grains
// release or stick, with a fresh budget.
detail::IntegrationResult<3> AdhesiveContactCollision::go_on_after_follow(detail::IntegrationResult<3> followed,
                                                                 IntegrationSettings settings,
                                                                 const detail::StepObserver<3>* observer) const {
  const bool certain = kinetic_at_release(followed.terminal.state) <= 0.0 ||
                       std::any_of(followed.hits.begin(), followed.hits.end(),
                                   [](const auto& hit) { return hit.id == sticks; });
  if (certain) return followed;
  const double t = followed.terminal.time;
  settings.max_time = t + 1e4 * t_hertz_;
  settings.max_steps = std::max(options_.max_steps - followed.steps, 1L);
  auto e = events(false);
  e[max_compression].armed = std::none_of(followed.hits.begin(), followed.hits.end(),
                                          [](const auto& hit) { return hit.id == max_compression; });
  auto rest = detail::integrate_until_event<3>(*this, followed.terminal.state, t, 1e-4 * t_hertz_, settings, e, observer);
  rest.hits.insert(rest.hits.begin(), followed.hits.begin(), followed.hits.end());
  rest.steps += followed.steps;
  return rest;
}

void AdhesiveContactCollision::finish(const detail::IntegrationResult<3>& result) {
  const State& end = result.terminal.state;
  for (const auto& hit : result.hits) {
    if (hit.id == max_compression) {
      out_.max_overlap = hit.state[0] * s_.length;
      out_.time_of_max_overlap = hit.time * s_.time;
    }
  }
  out_.steps = result.steps;
  // A settled run ends at the followed time itself (its scaled time times the unit rounds off).
  out_.contact_time = result.terminal.id == settled ? options_.follow_time : result.terminal.time * s_.time;
  if (follow_ && result.terminal.id != release) {
    out_.notes.push_back(detail::followed_note(options_.follow_time, out_.contact_time));
  } else if (result.hits.empty()) {  // stopped before the maximum compression
    out_.max_overlap = std::max(end[0], 0.0) * s_.length;
    out_.time_of_max_overlap = result.terminal.time * s_.time;
    out_.compression_unfinished = true;
    out_.notes.push_back(detail::before_max_compression_note);
  }
  const bool bounced = result.terminal.id == release;
  out_.energy.bulk_dissipated = end[2] * s_.energy;
  out_.energy.crack_dissipated = snap_release_;
  // Release at the fold (or the pull-off point): the pair jumps off, U_E + U_S there is dissipated.
  // The rate there is the balance's (kinetic_at_release); the integrated one measures the closure.
  const double delta = bounced ? delta_release_ : end[0] * s_.length;
  const double v = bounced ? -std::sqrt(std::max(kinetic_at_release(end), 0.0)) : end[1];
  detail::finish_adhesive(out_, s_, v, geometry_.elastic_energy(delta), geometry_.surface_energy(delta), bounced);
  if (bounced) out_.energy.closure_error = s_.energy * (v * v - end[1] * end[1]);
  if (options_.record_trajectory) record_end(result.terminal.time, end, bounced, v);
}

// The trajectory's end: the state there on the branch and, after a release, the same time past
// the jump off it (no contact, what it held released, the balance's rate).
void AdhesiveContactCollision::record_end(double t, const State& end, bool bounced, double v) {
  if (out_.trajectory.empty() || out_.trajectory.back().time < t * s_.time) trajectory_.add_end(sample(t, end));
  out_.trajectory.back().time = std::max(out_.trajectory.back().time, out_.contact_time);
  if (!bounced) return;
  TrajectorySample off = out_.trajectory.back();
  off.rate = v * s_.speed;
  off.contact_radius = off.elastic_force = off.dissipative_force = off.elastic = off.surface = 0.0;
  off.kinetic = 0.5 * p_.effective_mass * off.rate * off.rate;
  off.crack_dissipated = out_.energy.crack_dissipated;
  trajectory_.add_end(off);
}

CollisionOutcome AdhesiveContactCollision::run() {
  finish(integrate());
  return std::move(out_);
}

}  // namespace

CollisionOutcome integrate_adhesive_collision(const models::AdhesivePair& p, const models::AdhesiveGeometry& geometry,
                                              double speed, const AdhesiveCollisionOptions& options) {
  return AdhesiveContactCollision(p, geometry, speed, options).run();
}

CollisionOutcome integrate_jkr_viscoelastic_collision(const models::AdhesivePair& p, double speed,
                                                      const AdhesiveCollisionOptions& options) {
  const auto jkr = models::jkr_geometry(p.effective_radius, p.effective_modulus, p.surface_energy);
  return integrate_adhesive_collision(p, *jkr, speed, options);
}

}  // namespace bounce::dynamics

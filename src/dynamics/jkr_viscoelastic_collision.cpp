// `jkr-viscoelastic`: K13's equations with the contact radius held on the JKR equilibrium
// (an instantaneous crack, beta = 1) plus the bulk force (19). Not stiff: integrated with
// dopri5 (event_integrator.hpp).
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "adhesive_outcome.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/dynamics/adhesive_collision.hpp"
#include "event_integrator.hpp"
#include "krijt_system.hpp"

namespace bounce::dynamics {

namespace {

using detail::Scales;
using State = detail::State<3>;  // delta / L, rate / g, bulk dissipation / E0

// Where the contact breaks: at the fold delta_c (d delta / da = 0, the end K13 (25) assumes) or,
// as LAMMPS's `pair granular jkr` ends it, at the pull-off point (dF/da = 0, F = -(3/2) pi gamma R).
double release_overlap(const contact::jkr::Parameters& p, AdhesiveRelease release) {
  return release == AdhesiveRelease::pull_off ? contact::jkr::pull_off_overlap(p) : contact::jkr::separation_overlap(p);
}

// The events of the collision (their ids).
enum JkrEvent : int { max_compression, release, sticks, end_of_follow };

class JkrViscoelastic {
 public:
  JkrViscoelastic(const models::KrijtParameters& p, double speed, const AdhesiveCollisionOptions& options);
  CollisionOutcome run();
  // The system: K13 (20) with a on the JKR curve, and the bulk dissipation K13 (C.3).
  void operator()(const State& y, State& dydt, double) const;

 private:
  // (U_K + U_E + U_S) minus its value at the fold: below 0 the grains can never separate.
  double mechanical_minus_release(const State& y) const;
  std::vector<detail::Event<3>> events(bool following) const;
  detail::IntegrationResult<3> go_on_after_follow(detail::IntegrationResult<3> followed, IntegrationSettings settings,
                                                  const detail::StepObserver<3>* observer) const;
  TrajectorySample sample(double t, const State& y) const;
  detail::IntegrationResult<3> integrate();
  void finish(const detail::IntegrationResult<3>& result);

  const models::KrijtParameters& p_;
  const AdhesiveCollisionOptions& options_;
  const Scales s_;
  const contact::jkr::DisplacementBranch branch_;
  const double delta_release_, snap_release_, release_energy_, t_hertz_;
  const bool follow_;
  CollisionOutcome out_;
};

JkrViscoelastic::JkrViscoelastic(const models::KrijtParameters& p, double speed, const AdhesiveCollisionOptions& options)
    : p_(p), options_(options), s_(detail::scales_for(p, speed)), branch_({p.effective_radius, p.effective_modulus, p.surface_energy}),
      delta_release_(release_overlap({p.effective_radius, p.effective_modulus, p.surface_energy}, options.release)),
      // Snap-on at delta = 0: a jumps from 0 to the JKR radius; -(U_E + U_S) is released (crack).
      snap_release_(-models::contact_energy(
          p, contact::jkr::snap_on_contact_radius({p.effective_radius, p.effective_modulus, p.surface_energy}), 0.0)),
      // Release needs U_E + U_S = U(a, delta) > 0 at the release point; the mechanical energy
      // never increases, so once it is below that the grains can never separate.
      release_energy_(models::contact_energy(p, branch_.radius(delta_release_), delta_release_) / s_.energy),
      t_hertz_(detail::scaled_hertz_time(p, speed, s_)), follow_(options.follow_time > 0.0) {
  out_.method = "integrate";
}

void JkrViscoelastic::operator()(const State& y, State& dydt, double) const {
  const double delta = y[0] * s_.length, rate = y[1] * s_.speed;
  const double a = branch_.radius(delta);
  const double fd = models::bulk_dissipative_force(p_, a, rate);
  const double force = models::elastic_force(p_, a, delta) + fd;
  dydt[0] = y[1];
  dydt[1] = -force / p_.effective_mass * s_.time / s_.speed;  // K13 (20) with a on the JKR curve
  dydt[2] = fd * rate * s_.time / s_.energy;                  // K13 (C.3)
}

double JkrViscoelastic::mechanical_minus_release(const State& y) const {
  const double delta = y[0] * s_.length;
  return y[1] * y[1] + models::contact_energy(p_, branch_.radius(delta), delta) / s_.energy - release_energy_;
}

std::vector<detail::Event<3>> JkrViscoelastic::events(bool following) const {
  std::vector<detail::Event<3>> e(3);
  e[0] = {max_compression, [](double, const State& y) { return y[1]; }, -1, false, true, -1};
  e[1] = {release, [this](double, const State& y) { return y[0] - delta_release_ / s_.length; }, -1, true, true, -1};
  e[2] = {sticks, [this](double, const State& y) { return mechanical_minus_release(y); }, -1, !following, true, -1};
  if (following) {  // the end of a followed collision, with the state there
    const double end = options_.follow_time / s_.time;
    e.push_back({end_of_follow, [end](double t, const State&) { return end - t; }, -1, true, true, -1});
  }
  return e;
}

TrajectorySample JkrViscoelastic::sample(double t, const State& y) const {
  TrajectorySample x;
  x.time = t * s_.time;
  x.overlap = y[0] * s_.length;
  x.rate = y[1] * s_.speed;
  x.contact_radius = branch_.radius(x.overlap);
  x.elastic_force = models::elastic_force(p_, x.contact_radius, x.overlap);
  x.dissipative_force = models::bulk_dissipative_force(p_, x.contact_radius, x.rate);
  x.effective_surface_energy_ratio = 1.0;
  x.kinetic = 0.5 * p_.effective_mass * x.rate * x.rate;
  x.elastic = contact::independent::elastic_energy({p_.effective_radius, p_.effective_modulus}, x.contact_radius, x.overlap);
  x.surface = contact::independent::surface_energy(x.contact_radius, p_.surface_energy);
  x.crack_dissipated = snap_release_;
  x.bulk_dissipated = y[2] * s_.energy;
  return x;
}

detail::IntegrationResult<3> JkrViscoelastic::integrate() {
  IntegrationSettings settings;
  settings.relative_tolerance = settings.absolute_tolerance = options_.relative_tolerance * 1e-2;
  settings.max_steps = options_.max_steps;
  // A followed run ends at its end_of_follow event; the budget lies beyond it.
  settings.max_time = follow_ ? 2.0 * options_.follow_time / s_.time : 1e4 * t_hertz_;
  const double spacing = 2.0 * t_hertz_ / std::max(options_.trajectory_points, 1);
  double next_sample = spacing;  // the start is sampled below
  const detail::StepObserver<3> observer = [&](double t0, double t1, const auto& at) {
    for (; next_sample <= t1; next_sample += spacing) {
      if (next_sample >= t0) out_.trajectory.push_back(sample(next_sample, at(next_sample)));
    }
  };
  const State start{0.0, 1.0, 0.0};
  if (options_.record_trajectory) out_.trajectory.push_back(sample(0.0, start));
  if (!follow_ && mechanical_minus_release(start) <= 0.0) {
    detail::IntegrationResult<3> bound;
    bound.terminal = {sticks, 0.0, start};  // bound from the snap-on on
    return bound;
  }
  auto e = events(follow_);
  const detail::StepObserver<3>* watch = options_.record_trajectory ? &observer : nullptr;
  auto result = detail::integrate_until_event<3>(*this, start, 0.0, 1e-4 * t_hertz_, settings, e, watch);
  return result.terminal.id == end_of_follow ? go_on_after_follow(std::move(result), settings, watch) : result;
}

// The followed time has come: with sticking certain (the energy below the release energy,
// now or at a `sticks` hit) the run ends there; otherwise the outcome is still open (a time
// shorter than the collision) and the run goes on as an unfollowed one until the grains
// release or stick, with a fresh budget.
detail::IntegrationResult<3> JkrViscoelastic::go_on_after_follow(detail::IntegrationResult<3> followed,
                                                                 IntegrationSettings settings,
                                                                 const detail::StepObserver<3>* observer) const {
  const bool certain = mechanical_minus_release(followed.terminal.state) <= 0.0 ||
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

void JkrViscoelastic::finish(const detail::IntegrationResult<3>& result) {
  const State& end = result.terminal.state;
  for (const auto& hit : result.hits) {
    if (hit.id == max_compression) {
      out_.max_overlap = hit.state[0] * s_.length;
      out_.time_of_max_overlap = hit.time * s_.time;
    }
  }
  out_.steps = result.steps;
  out_.contact_time = result.terminal.time * s_.time;
  if (follow_ && result.terminal.id != release) {
    out_.notes.push_back(detail::followed_note(options_.follow_time, out_.contact_time));
  } else if (result.hits.empty()) {  // stopped before the maximum compression
    out_.max_overlap = std::max(end[0], 0.0) * s_.length;
    out_.time_of_max_overlap = result.terminal.time * s_.time;
    out_.notes.push_back(detail::before_max_compression_note);
  }
  const bool bounced = result.terminal.id == release;
  out_.energy.bulk_dissipated = end[2] * s_.energy;
  out_.energy.crack_dissipated = snap_release_;
  // Release at the fold (or the pull-off point): a drops to 0 there, U_E + U_S there is dissipated.
  const double delta = bounced ? delta_release_ : end[0] * s_.length;
  detail::finish_adhesive(out_, p_, s_, end[1], branch_.radius(delta), delta, bounced);
  if (options_.record_trajectory && !out_.trajectory.empty() && bounced) {
    out_.trajectory.back().crack_dissipated = out_.energy.crack_dissipated;
  }
}

CollisionOutcome JkrViscoelastic::run() {
  finish(integrate());
  return std::move(out_);
}

}  // namespace

CollisionOutcome integrate_jkr_viscoelastic_collision(const models::KrijtParameters& p, double speed,
                                                      const AdhesiveCollisionOptions& options) {
  return JkrViscoelastic(p, speed, options).run();
}

}  // namespace bounce::dynamics

#include "bounce/dynamics/normal_collision.hpp"

#include <cmath>
#include <vector>

#include "bounce/core/error.hpp"
#include "event_integrator.hpp"
#include "normal_system.hpp"

namespace bounce::dynamics {

namespace {

using State = detail::State<3>;  // x = xi/xi0, v = xi'/g, dissipated work / (m g^2)

struct ScaledSystem {
  detail::NormalScaled normal;
  void operator()(const State& y, State& dydt, double /*t*/) const { normal(y, dydt); }
};

// The scales of a collision's scaled state (overlap xi0, speed, time, energy) and its mass.
struct SampleScales {
  double xi0, speed, time_unit, energy_unit, effective_mass;
};

// A trajectory row from the scaled state y = (xi / xi0, rate / speed, dissipated / energy) at
// scaled time t.
TrajectorySample trajectory_sample(const models::NormalForceModel& model, const SampleScales& u, double t,
                                   const State& y) {
  const double xi = u.xi0 * y[0];
  const double rate = u.speed * y[1];
  TrajectorySample s;
  s.time = t * u.time_unit;
  s.overlap = xi;
  s.rate = rate;
  s.contact_radius = model.contact_radius(xi);
  s.elastic_force = model.elastic_force(xi);
  s.dissipative_force = model.force(xi, rate) - s.elastic_force;
  s.kinetic = 0.5 * u.effective_mass * rate * rate;
  s.elastic = model.elastic_energy(xi);
  s.bulk_dissipated = y[2] * u.energy_unit;
  return s;
}

}  // namespace

CollisionOutcome integrate_normal_collision(const models::NormalForceModel& model,
                                            double effective_mass, double speed,
                                            const NormalCollisionOptions& options) {
  model.check_speed(speed);
  const double xi0 = model.reference_overlap(speed);
  const double time_unit = xi0 / speed;
  const double energy_unit = effective_mass * speed * speed;
  const ScaledSystem system{{&model, xi0, speed, xi0 / energy_unit}};

  const double cutoff = model.cutoff_overlap(speed) / xi0;  // 0 unless the force is singular at contact
  std::vector<detail::Event<3>> events =
      detail::normal_events<3>(model, options.end_rule, cutoff, xi0, speed, energy_unit);

  CollisionOutcome out;
  out.method = "integrate";
  const State start{cutoff, 1.0, 0.0};

  const SampleScales scales{xi0, speed, time_unit, energy_unit, effective_mass};
  auto sample = [&](double t, const State& y) { return trajectory_sample(model, scales, t, y); };
  TrajectoryRecorder trajectory(out.trajectory, out.trajectory_thinning);
  // Elastic Hertz contact lasts 2.94 scaled units (BSHP96 (A13)).
  const double spacing = 2.94 / std::max(options.trajectory_points, 1);
  double next_sample = spacing;  // the start is sampled below
  const detail::StepObserver<3> observer = [&](double t0, double t1, const auto& at) {
    for (; next_sample <= t1; next_sample += trajectory.step(spacing, time_unit)) {
      if (next_sample >= t0) trajectory.add(sample(next_sample, at(next_sample)));
    }
  };
  if (options.record_trajectory) trajectory.add(sample(0.0, start));

  auto result = detail::integrate_until_event<3>(system, start, 0.0, 1e-3, options.integration, events,
                                                 options.record_trajectory ? &observer : nullptr);
  const State& end = result.terminal.state;
  if (options.record_trajectory) trajectory.add_end(sample(result.terminal.time, end));

  out.steps = result.steps;
  detail::NormalEnd normal_end;
  normal_end.time = result.terminal.time;
  normal_end.x = end[0];
  normal_end.v = end[1];
  normal_end.dissipated = end[2];
  normal_end.stuck = result.terminal.id == detail::id(detail::CollisionEvent::sticks);
  for (const auto& hit : result.hits) {
    if (hit.id == detail::id(detail::CollisionEvent::max_compression)) {
      normal_end.compressed = true;
      normal_end.max_overlap = hit.state[0];
      normal_end.max_overlap_time = hit.time;
    }
  }
  detail::finish_normal_outcome(out, normal_end, model, xi0, time_unit, energy_unit);
  return out;
}

}  // namespace bounce::dynamics

#include "bounce/dynamics/normal_collision.hpp"

#include <cmath>
#include <vector>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "event_integrator.hpp"

namespace bounce::dynamics {

namespace {

using State = detail::State<3>;  // x = xi/xi0, v = xi'/g, dissipated work / (m g^2)

struct ScaledSystem {
  const models::NormalForceModel* model;
  double xi0;
  double speed;
  double force_to_acceleration;  // xi0 / (m g^2): scaled acceleration per newton

  void operator()(const State& y, State& dydt, double /*t*/) const {
    const double xi = xi0 * y[0];
    const double rate = speed * y[1];
    const double total = model->force(xi, rate);
    const double elastic = model->elastic_force(xi);
    dydt[0] = y[1];
    dydt[1] = -total * force_to_acceleration;
    dydt[2] = (total - elastic) * y[1] * force_to_acceleration;  // dissipative power >= 0
  }
};

}  // namespace

CollisionOutcome integrate_normal_collision(const models::NormalForceModel& model,
                                            double effective_mass, double speed,
                                            const NormalCollisionOptions& options) {
  require_positive("velocity", speed, "impact velocity [m/s]");
  require_positive("effective_mass", effective_mass, "effective mass [kg]");
  const double xi0 = model.reference_overlap(speed);
  const double time_unit = xi0 / speed;
  const double energy_unit = effective_mass * speed * speed;
  const ScaledSystem system{&model, xi0, speed, xi0 / energy_unit};

  const double cutoff = model.cutoff_overlap(speed) / xi0;  // 0 unless the force is singular at contact
  std::vector<detail::Event<3>> events(4);
  // 0: maximum compression (xi' falls through zero); arms the end-of-contact event.
  events[0].g = [](double, const State& y) { return y[1]; };
  events[0].direction = -1;
  events[0].terminal = false;
  events[0].arms = 1;
  // 1: end of contact.
  if (options.end_rule == EndRule::overlap) {
    events[1].g = [cutoff](double, const State& y) { return y[0] - cutoff; };
  } else {
    events[1].g = [&](double, const State& y) {
      return model.force_sign(xi0 * y[0], speed * y[1]);
    };
  }
  events[1].direction = -1;
  events[1].terminal = true;
  events[1].armed = false;
  // 2: under the force rule the contact ends at the latest when the overlap returns to 0.
  events[2].g = [](double, const State& y) { return y[0]; };
  events[2].direction = -1;
  events[2].terminal = true;
  events[2].armed = options.end_rule == EndRule::force;
  // 3: adhesive laws: the mechanical energy (1/2) xi'^2 + U(xi)/m never increases and
  // must be >= 0 at separation (U(0) = 0): once negative, the grains stick.
  auto mechanical = [&](const State& y) {
    return 0.5 * y[1] * y[1] + model.elastic_energy(xi0 * y[0]) / energy_unit;
  };
  events[3].g = [&](double, const State& y) { return mechanical(y); };
  events[3].direction = -1;
  events[3].terminal = true;
  events[3].armed = model.adhesive();
  if (model.adhesive() && options.end_rule == EndRule::force) {
    throw InvalidArgument("contact_end", "force",
                          "overlap for adhesive models (their contact ends when the overlap returns to 0)");
  }

  CollisionOutcome out;
  out.method = "integrate";
  const State start{cutoff, 1.0, 0.0};

  auto sample = [&](double t, const State& y) {
    const double xi = xi0 * y[0];
    const double rate = speed * y[1];
    TrajectorySample s;
    s.time = t * time_unit;
    s.overlap = xi;
    s.rate = rate;
    s.contact_radius = model.contact_radius(xi);
    s.elastic_force = model.elastic_force(xi);
    s.dissipative_force = model.force(xi, rate) - s.elastic_force;
    s.kinetic = 0.5 * effective_mass * rate * rate;
    s.elastic = model.elastic_energy(xi);
    s.bulk_dissipated = y[2] * energy_unit;
    out.trajectory.push_back(s);
  };
  // Elastic Hertz contact lasts 2.94 scaled units (BSHP96 (A13)).
  const double spacing = 2.94 / std::max(options.trajectory_points, 1);
  double next_sample = 0.0;
  const detail::StepObserver<3> observer = [&](double t0, double t1, const auto& at) {
    for (; next_sample <= t1; next_sample += spacing) {
      if (next_sample >= t0) sample(next_sample, at(next_sample));
    }
  };
  if (options.record_trajectory) sample(0.0, start);

  auto result = detail::integrate_until_event<3>(system, start, 0.0, 1e-3, options.integration, events,
                                                 options.record_trajectory ? &observer : nullptr);
  const State& end = result.terminal.state;
  if (options.record_trajectory) sample(result.terminal.time, end);

  out.steps = result.steps;
  const bool stuck = result.terminal.index == 3;
  out.cor = stuck ? 0.0 : -end[1];
  out.outcome = stuck ? Outcome::stick : Outcome::bounce;
  out.contact_time = result.terminal.time * time_unit;
  for (const auto& hit : result.hits) {
    if (hit.index == 0) {
      out.max_overlap = hit.state[0] * xi0;
      out.time_of_max_overlap = hit.time * time_unit;
    }
  }
  if (stuck && result.hits.empty()) {  // sticking certain while still compressing
    out.max_overlap = end[0] * xi0;
    out.time_of_max_overlap = out.contact_time;
    out.notes.push_back(
        "sticking was certain before the maximum compression: max_overlap is the overlap at that time");
  }
  EnergyBudget& e = out.energy;
  e.initial_kinetic = 0.5 * energy_unit;
  e.final_kinetic = 0.5 * energy_unit * end[1] * end[1];
  e.bulk_dissipated = end[2] * energy_unit;
  e.elastic_remaining = model.elastic_energy(xi0 * end[0]);
  e.closure_error = e.initial_kinetic - e.final_kinetic - e.bulk_dissipated - e.elastic_remaining;
  return out;
}

}  // namespace bounce::dynamics

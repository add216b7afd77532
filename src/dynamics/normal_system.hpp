#pragma once
// Private: the normal collision in the scaled units of BP04 (8.66), shared by the
// head-on (normal_collision.cpp) and the oblique (tangential_collision.cpp)
// integrations. The first three state components are x = xi/xi0, v = xi'/g and the
// dissipated work / (m g^2); an oblique collision appends its tangential ones.

#include <cmath>
#include <string>
#include <vector>

#include "bounce/core/error.hpp"
#include "bounce/dynamics/normal_collision.hpp"
#include "event_integrator.hpp"

namespace bounce::dynamics::detail {

using models::EndRule;

struct NormalScaled {
  const models::NormalForceModel* model;
  double xi0;
  double speed;
  double force_to_acceleration;  // xi0 / (m g^2): scaled acceleration per newton

  /// d/dt of components 0-2; returns the scaled normal force f = -x'' (>= 0: repulsive).
  template <std::size_t N>
  double operator()(const State<N>& y, State<N>& dydt) const {
    const double xi = xi0 * y[0];
    const double rate = speed * y[1];
    const double total = model->force(xi, rate);
    const double elastic = model->elastic_force(xi);
    const double f = total * force_to_acceleration;
    dydt[0] = y[1];
    dydt[1] = -f;
    dydt[2] = (total - elastic) * y[1] * force_to_acceleration;  // dissipative power >= 0
    return f;
  }
};

/// The events of a normal collision (their ids), and those an oblique one adds.
enum class CollisionEvent {
  max_compression,  ///< xi' = 0: arms end_of_contact
  end_of_contact,   ///< under the end rule: xi back to the cutoff, or the force vanishing
  overlap_zero,     ///< under the force rule: the overlap returning to 0 first
  sticks,           ///< adhesive laws: the mechanical energy turning negative (never separate)
  asperity_break,   ///< the tangential spring reaching mu F^N
  mode_change,      ///< to or from the averaged sawtooth of dense breaking
  end_of_record,    ///< the end of a recorded normal force (integrate_tangential_motion)
};
constexpr int id(CollisionEvent e) { return static_cast<int>(e); }

template <std::size_t N>
Event<N> make_event(CollisionEvent which, std::function<double(double, const State<N>&)> g, bool terminal, bool armed) {
  Event<N> e;
  e.id = id(which);
  e.g = std::move(g);
  e.direction = -1;
  e.terminal = terminal;
  e.armed = armed;
  return e;
}

/// The events of a normal collision under `rule` (cutoff: the scaled overlap where the
/// contact starts and ends).
template <std::size_t N>
std::vector<Event<N>> normal_events(const models::NormalForceModel& model, EndRule rule, double cutoff, double xi0,
                                    double speed, double energy_unit) {
  std::vector<Event<N>> events;
  events.push_back(make_event<N>(CollisionEvent::max_compression, [](double, const State<N>& y) { return y[1]; },
                                 false, true));
  events.back().arms = id(CollisionEvent::end_of_contact);
  if (rule == EndRule::overlap) {
    events.push_back(make_event<N>(CollisionEvent::end_of_contact,
                                   [cutoff](double, const State<N>& y) { return y[0] - cutoff; }, true, false));
  } else {
    events.push_back(make_event<N>(
        CollisionEvent::end_of_contact,
        [&model, xi0, speed](double, const State<N>& y) { return model.force_sign(xi0 * y[0], speed * y[1]); }, true,
        false));
  }
  events.push_back(make_event<N>(CollisionEvent::overlap_zero, [](double, const State<N>& y) { return y[0]; }, true,
                                 rule == EndRule::force));
  // (1/2) xi'^2 + U(xi)/m never increases and must be >= 0 at separation (U(0) = 0).
  events.push_back(make_event<N>(
      CollisionEvent::sticks,
      [&model, xi0, energy_unit](double, const State<N>& y) {
        return 0.5 * y[1] * y[1] + model.elastic_energy(xi0 * y[0]) / energy_unit;
      },
      true, model.adhesive()));
  return events;
}

/// The normal outcome from the end state of the first three components.
struct NormalEnd {
  double time = 0.0;           ///< scaled
  double x = 0.0, v = 0.0, dissipated = 0.0;
  bool stuck = false;
  bool compressed = false;     ///< the maximum compression was reached
  double max_overlap_time = 0.0, max_overlap = 0.0;  ///< scaled
};

inline void finish_normal_outcome(CollisionOutcome& out, const NormalEnd& end, const models::NormalForceModel& model,
                                  double xi0, double time_unit, double energy_unit) {
  out.cor = end.stuck ? 0.0 : -end.v;
  out.outcome = end.stuck ? Outcome::stick : Outcome::bounce;
  out.contact_time = end.time * time_unit;
  if (end.compressed) {
    out.max_overlap = end.max_overlap * xi0;
    out.time_of_max_overlap = end.max_overlap_time * time_unit;
  } else if (end.stuck) {  // sticking certain while still compressing
    out.max_overlap = end.x * xi0;
    out.time_of_max_overlap = out.contact_time;
    out.compression_unfinished = true;
    out.notes.push_back("sticking was certain before the maximum compression, which max_overlap (null) therefore "
                        "does not give");
  }
  EnergyBudget& e = out.energy;
  e.initial_kinetic = 0.5 * energy_unit;
  e.final_kinetic = 0.5 * energy_unit * end.v * end.v;
  e.bulk_dissipated = end.dissipated * energy_unit;
  e.surface_remaining = model.adhesive_energy(xi0 * end.x);
  e.elastic_remaining = model.elastic_energy(xi0 * end.x) - e.surface_remaining;
  e.close();
}

}  // namespace bounce::dynamics::detail

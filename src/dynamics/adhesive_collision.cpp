#include "bounce/dynamics/adhesive_collision.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

#include "bounce/contact/hertz.hpp"
#include "bounce/contact/independent.hpp"
#include "bounce/contact/jkr.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/crack.hpp"
#include "bounce/pair/mixing.hpp"
#include "event_integrator.hpp"
#include "krijt_system.hpp"
#include "stiff.hpp"

namespace bounce::dynamics {

namespace {

using detail::closing_exit;
using detail::pi;
using detail::KrijtSystem;
using detail::Phase;
using detail::Scales;
using detail::scaled_hertz_time;
using detail::scales_for;

constexpr const char* before_max_compression_note =
    "sticking was certain before the maximum compression: max_overlap is the overlap at that time (--follow "
    "integrates the settling)";

// 2 pi a_eq^2 gamma / ((1/2) m g^2): the adhesion energy in units of the impact energy.
double adhesion_energy_ratio(const models::KrijtParameters& p, const Scales& s) {
  const contact::jkr::Parameters j{p.effective_radius, p.effective_modulus, p.surface_energy};
  const double a = contact::jkr::equilibrium_contact_radius(j);
  return 2.0 * pi * a * a * p.surface_energy / s.energy;
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
  out.elastic = contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, out.contact_radius, out.overlap);
  out.surface = contact::independent::surface_energy(out.contact_radius, p.surface_energy);
  out.crack_dissipated = y[3] * s.energy;
  out.bulk_dissipated = y[4] * s.energy;
  return out;
}

void check_parameters(const models::KrijtParameters& p, double speed) {
  require_positive("velocity", speed, "impact velocity [m/s]");
  require_positive("gamma", p.surface_energy, "surface energy gamma [J/m^2] (adhesive model)");
  require_positive("tvis", p.relaxation_time, "viscous relaxation time T_vis [s]");
  require_non_negative("A", p.dissipative_constant, "dissipative constant A [s]");
  require_positive("z0", p.z0, "equilibrium separation z0 [m]");
  require_open_interval("k", p.k, 0.0, 1.0, "k");
}

}  // namespace

namespace {

// One contact episode: from first touch (delta = 0, speed g) to the run-away of the
// crack or sticking. `approaching` reports a break with delta' > 0 (the grains were
// pulled back by the adhesive neck when it ruptured: they will meet again).
struct Episode {
  CollisionOutcome outcome;
  double final_overlap = 0.0;  // delta at the break [m]
  double final_rate = 0.0;     // delta' at the break [m/s]
  bool approaching = false;
};

Episode krijt_episode(const models::KrijtParameters& p, double speed, const AdhesiveCollisionOptions& options) {
  const Scales s = scales_for(p, speed);
  const models::InitialContact start = models::krijt_initial_contact(p);
  const bool follow = options.follow_time > 0.0;
  KrijtSystem system(p, s, !follow, options.break_margin);
  const std::vector<double> y0 = {0.0, 1.0, start.contact_radius / s.radius, start.crack_dissipated / s.energy, 0.0};
  const double t_hertz = scaled_hertz_time(p, speed, s);
  const double t_start = start.time / s.time;
  const double time_limit = follow ? options.follow_time / s.time : 1e4 * t_hertz;
  system.set_time_limit(time_limit);
  detail::StiffSettings settings;
  // The energies exchanged reach the adhesion energy 2 pi a_eq^2 gamma, which can exceed
  // the impact energy (the unit) by orders of magnitude in slow collisions: a relative
  // error tol in a then costs tol * 2 pi a_eq^2 gamma / E0 in the energy budget. The
  // tolerance is tightened by that ratio so that the budget closes to ~tol of E0.
  const double tolerance = options.relative_tolerance * std::min(1.0, 1.0 / adhesion_energy_ratio(p, s));
  settings.relative_tolerance = tolerance;
  settings.absolute_tolerance.assign(5, tolerance * 1e-2);
  settings.event_directions.assign(6, -1);

  CollisionOutcome out;
  out.method = "integrate";
  const double spacing = 2.0 * t_hertz / std::max(options.trajectory_points, 1);
  double next_sample = t_start;
  if (options.record_trajectory) out.trajectory.push_back(krijt_sample(p, s, t_start, y0));
  std::vector<double> y = y0;
  double t = t_start;
  long steps = 0;
  bool compressed = false;  // the maximum compression was passed
  // Bound from the start: the formation already took more than the kinetic energy.
  bool ended = !follow && system.mechanical_energy(y0.data()) <= 0.0;
  if (ended) out.outcome = Outcome::stick;
  Phase phase = system.physical(y0.data()).beta < closing_exit ? Phase::closing : Phase::time;
  constexpr int a_index = 2;
  while (!ended) {
    system.set_phase(phase);
    // In the a phases the state holds t in place of a, and s = +-a increases.
    const double sign = phase == Phase::opening ? -1.0 : 1.0;
    const detail::SwappedIndependent swapped(system, a_index, sign);
    const detail::StiffSystem& equations = phase == Phase::time ? static_cast<const detail::StiffSystem&>(system) : swapped;
    std::vector<double> z = y;
    double s0 = t;
    settings.max_time = time_limit;
    if (phase != Phase::time) {
      z[a_index] = t;
      s0 = sign * y[a_index];
      settings.max_time = phase == Phase::opening ? 0.0 : 1e6;  // a = 0; a bound never reached
    }
    settings.max_steps = options.max_steps - steps;
    const std::unique_ptr<detail::StiffIntegrator> engine =
        detail::make_stiff_integrator(options.engine, equations, z, s0, settings);
    detail::StiffIntegrator& integrator = *engine;
    if (compressed) integrator.disable_event(0);
    // State and time at s inside the last step, and the state at time `when` (the
    // time is monotone in s in every phase).
    auto state_at_time = [&](double when, double s_lo, double s_hi) {
      if (phase == Phase::time) return integrator.state_at(when);
      auto gap = [&](double x) { return integrator.state_at(x)[a_index] - when; };
      boost::uintmax_t iterations = 60;
      const auto root = boost::math::tools::toms748_solve(gap, s_lo, s_hi, boost::math::tools::eps_tolerance<double>(50),
                                                          iterations);
      const double x = 0.5 * (root.first + root.second);
      return swapped.original(x, integrator.state_at(x).data());
    };
    Phase next = phase;
    while (!ended && next == phase) {
      detail::StiffIntegrator::Step step;
      try {
        step = integrator.step();
      } catch (const TimeBudgetExceeded&) {
        if (!follow) throw;
        ended = true;  // a followed collision reached its end time
        break;
      }
      z = integrator.state();
      const double t_before = t;
      if (phase == Phase::time) {
        y = z;
        t = step.t1;
      } else {
        y = swapped.original(step.t1, z.data());
        t = z[a_index];
      }
      if (options.record_trajectory) {
        for (; next_sample < t; next_sample += spacing) {
          if (next_sample > t_before) {
            out.trajectory.push_back(krijt_sample(p, s, next_sample, state_at_time(next_sample, step.t0, step.t1)));
          }
        }
        out.trajectory.push_back(krijt_sample(p, s, t, y));
      }
      for (int event : step.fired) {
        if (event == 0) {
          out.max_overlap = y[0] * s.length;
          out.time_of_max_overlap = t * s.time;
          compressed = true;
          integrator.disable_event(0);
        } else if (event == 1) {
          out.outcome = Outcome::bounce;
          ended = true;
        } else if (event == 2) {
          out.outcome = Outcome::stick;
          ended = true;
        } else if (event == 3 || event == 4) {
          next = phase != Phase::time ? Phase::time : event == 3 ? Phase::closing : Phase::opening;
        } else if (event == 5) {
          if (!follow) {
            throw TimeBudgetExceeded(fmt::format("the K13 collision lasted more than {:.3g} s without an outcome",
                                                 t * s.time));
          }
          ended = true;
        }
      }
    }
    steps += integrator.steps();
    phase = next;
  }
  if (!compressed && out.outcome == Outcome::stick && !follow) {  // stopped while still compressing
    out.max_overlap = std::max(y[0], 0.0) * s.length;
    out.time_of_max_overlap = t * s.time;
    out.notes.push_back(before_max_compression_note);
  }
  // A followed collision that never broke off is a sticking one.
  if (follow && !(out.outcome == Outcome::bounce && ended)) out.outcome = Outcome::stick;
  Episode episode;
  episode.final_overlap = y[0] * s.length;
  episode.final_rate = y[1] * s.speed;
  episode.approaching = out.outcome == Outcome::bounce && y[1] > 0.0;
  out.steps = steps;
  out.contact_time = t * s.time;
  const double a = y[2] * s.radius, delta = y[0] * s.length;
  EnergyBudget& e = out.energy;
  e.initial_kinetic = s.energy;
  e.bulk_dissipated = y[4] * s.energy;
  e.crack_dissipated = y[3] * s.energy;
  e.final_kinetic = s.energy * y[1] * y[1];  // for sticking: the kinetic energy at the end
  if (out.outcome == Outcome::bounce) {
    out.cor = -y[1];
    // The run-away from beta = 1/k to a = 0 is instantaneous: what U_E + U_S holds
    // then is released at the crack.
    e.crack_dissipated += models::contact_energy(p, a, delta);
  } else {
    out.cor = 0.0;
    e.elastic_remaining = contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, a, delta);
    e.surface_remaining = contact::independent::surface_energy(a, p.surface_energy);
  }
  e.close();
  episode.outcome = std::move(out);
  return episode;
}

}  // namespace

namespace {
CollisionOutcome krijt_collision(const models::KrijtParameters& p, double speed, const AdhesiveCollisionOptions& options);
}  // namespace

CollisionOutcome integrate_krijt_collision(const models::KrijtParameters& p, double speed,
                                           const AdhesiveCollisionOptions& options) {
  check_parameters(p, speed);
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
    CollisionOutcome out = krijt_collision(p, speed, cvode);
    out.notes.push_back(fmt::format("computed with CVODE: RODAS stopped ({})", e.what()));
    return out;
  }
}

namespace {

CollisionOutcome krijt_collision(const models::KrijtParameters& p, double speed,
                                 const AdhesiveCollisionOptions& options) {
  Episode first = krijt_episode(p, speed, options);
  CollisionOutcome out = std::move(first.outcome);
  double rate = first.final_rate, overlap = first.final_overlap;
  bool approaching = first.approaching;
  // A break while approaching (delta < 0 there: the surfaces are apart): free flight to
  // delta = 0, then a new contact with K13's initial condition at that speed.
  for (int episodes = 1; approaching; ++episodes) {
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
    Episode next = krijt_episode(p, rate, options);
    const CollisionOutcome& n = next.outcome;
    for (TrajectorySample sample : n.trajectory) {
      sample.time += shift;
      sample.bulk_dissipated += out.energy.bulk_dissipated;
      sample.crack_dissipated += out.energy.crack_dissipated;
      out.trajectory.push_back(sample);
    }
    out.outcome = n.outcome;
    out.cor = n.cor * rate / speed;  // rebound speed relative to the first impact speed
    out.contact_time = shift + n.contact_time;
    out.max_overlap = std::max(out.max_overlap, n.max_overlap);
    out.steps += n.steps;
    out.energy.bulk_dissipated += n.energy.bulk_dissipated;
    out.energy.crack_dissipated += n.energy.crack_dissipated;
    out.energy.final_kinetic = n.energy.final_kinetic;
    out.energy.elastic_remaining = n.energy.elastic_remaining;
    out.energy.surface_remaining = n.energy.surface_remaining;
    out.notes.insert(out.notes.end(), n.notes.begin(), n.notes.end());
    rate = next.final_rate;
    overlap = next.final_overlap;
    approaching = next.approaching;
  }
  EnergyBudget& e = out.energy;
  e.close();
  return out;
}

}  // namespace

// --- jkr-viscoelastic: the crack held on the JKR equilibrium -----------------------

namespace {

// Contact radius on the JKR branch stable under displacement control, a >= a_c:
// with u = sqrt(a), K13 (8) is u^4 - c R u - R delta = 0, c = sqrt(2 pi gamma / E*);
// Newton from above converges monotonically (the quartic is convex for u > u_c).
class JkrBranch {
 public:
  explicit JkrBranch(const models::KrijtParameters& p)
      : r_(p.effective_radius), c_(std::sqrt(2.0 * pi * p.surface_energy / p.effective_modulus)),
        u_fold_(std::cbrt(c_ * r_ / 4.0)) {}

  double radius(double delta) const {
    const double cr = c_ * r_;
    auto h = [&](double u) { return u * u * u * u - cr * u - r_ * delta; };
    double u = std::max(2.0 * u_fold_, std::sqrt(std::sqrt(std::max(2.0 * r_ * delta, 0.0))));
    while (h(u) < 0.0) u *= 2.0;
    for (int i = 0; i < 60; ++i) {
      const double step = h(u) / (4.0 * u * u * u - cr);
      u -= step;
      if (u <= u_fold_) {
        u = u_fold_;
        break;
      }
      if (std::abs(step) <= 1e-16 * u) break;
    }
    return u * u;
  }

 private:
  double r_, c_, u_fold_;
};

}  // namespace

CollisionOutcome integrate_jkr_viscoelastic_collision(const models::KrijtParameters& p, double speed,
                                                      const AdhesiveCollisionOptions& options) {
  require_positive("velocity", speed, "impact velocity [m/s]");
  require_positive("gamma", p.surface_energy, "surface energy gamma [J/m^2] (adhesive model)");
  require_non_negative("A", p.dissipative_constant, "dissipative constant A [s]");
  const Scales s = scales_for(p, speed);
  const JkrBranch branch(p);
  const contact::jkr::Parameters j{p.effective_radius, p.effective_modulus, p.surface_energy};
  const double delta_c = contact::jkr::separation_overlap(j);
  // Snap-on at delta = 0: a jumps from 0 to the JKR radius; -(U_E + U_S) is released (crack).
  const double snap_release = -models::contact_energy(p, contact::jkr::snap_on_contact_radius(j), 0.0);
  // Release needs U_E + U_S = U(a_c, delta_c) > 0 at the fold; the mechanical energy
  // never increases, so once it is below that the grains can never separate.
  const double release_energy = models::contact_energy(p, branch.radius(delta_c), delta_c) / s.energy;
  const bool follow = options.follow_time > 0.0;

  using State = detail::State<3>;  // delta / L, rate / g, bulk dissipation / E0
  struct System {
    const models::KrijtParameters* p;
    const JkrBranch* branch;
    Scales s;
    void operator()(const State& y, State& dydt, double) const {
      const double delta = y[0] * s.length, rate = y[1] * s.speed;
      const double a = branch->radius(delta);
      const double fd = models::bulk_dissipative_force(*p, a, rate);
      const double force = models::elastic_force(*p, a, delta) + fd;
      dydt[0] = y[1];
      dydt[1] = -force / p->effective_mass * s.time / s.speed;  // K13 (20) with a on the JKR curve
      dydt[2] = fd * rate * s.time / s.energy;                  // K13 (C.3)
    }
  } system{&p, &branch, s};
  auto mechanical_minus_release = [&](const State& y) {
    const double delta = y[0] * s.length;
    return y[1] * y[1] + models::contact_energy(p, branch.radius(delta), delta) / s.energy - release_energy;
  };
  std::vector<detail::Event<3>> events(3);
  events[0] = {[](double, const State& y) { return y[1]; }, -1, false, true, -1};                      // max compression
  events[1] = {[&](double, const State& y) { return y[0] - delta_c / s.length; }, -1, true, true, -1};  // release
  events[2] = {[&](double, const State& y) { return mechanical_minus_release(y); }, -1, !follow, true, -1};
  IntegrationSettings settings;
  settings.relative_tolerance = settings.absolute_tolerance = options.relative_tolerance * 1e-2;
  settings.max_steps = options.max_steps;
  const double t_hertz = scaled_hertz_time(p, speed, s);
  settings.max_time = follow ? options.follow_time / s.time : 1e4 * t_hertz;

  CollisionOutcome out;
  out.method = "integrate";
  auto sample = [&](double t, const State& y) {
    TrajectorySample x;
    x.time = t * s.time;
    x.overlap = y[0] * s.length;
    x.rate = y[1] * s.speed;
    x.contact_radius = branch.radius(x.overlap);
    x.elastic_force = models::elastic_force(p, x.contact_radius, x.overlap);
    x.dissipative_force = models::bulk_dissipative_force(p, x.contact_radius, x.rate);
    x.effective_surface_energy_ratio = 1.0;
    x.kinetic = 0.5 * p.effective_mass * x.rate * x.rate;
    x.elastic = contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, x.contact_radius, x.overlap);
    x.surface = contact::independent::surface_energy(x.contact_radius, p.surface_energy);
    x.crack_dissipated = snap_release;
    x.bulk_dissipated = y[2] * s.energy;
    out.trajectory.push_back(x);
  };
  const double spacing = 2.0 * t_hertz / std::max(options.trajectory_points, 1);
  double next_sample = 0.0;
  const detail::StepObserver<3> observer = [&](double t0, double t1, const auto& at) {
    for (; next_sample <= t1; next_sample += spacing) {
      if (next_sample >= t0) sample(next_sample, at(next_sample));
    }
  };
  const State start{0.0, 1.0, 0.0};
  if (options.record_trajectory) sample(0.0, start);
  detail::IntegrationResult<3> result;
  bool followed_to_end = false;
  if (!follow && mechanical_minus_release(start) <= 0.0) {
    result.terminal = {2, 0.0, start};  // bound from the snap-on on
  } else {
    try {
      result = detail::integrate_until_event<3>(system, start, 0.0, 1e-4 * t_hertz, settings, events,
                                                options.record_trajectory ? &observer : nullptr);
    } catch (const TimeBudgetExceeded&) {
      if (!follow) throw;
      followed_to_end = true;
    }
  }
  const State& end = followed_to_end && !out.trajectory.empty()
                         ? State{out.trajectory.back().overlap / s.length, out.trajectory.back().rate / s.speed,
                                 out.trajectory.back().bulk_dissipated / s.energy}
                         : result.terminal.state;
  for (const auto& hit : result.hits) {
    if (hit.index == 0) {
      out.max_overlap = hit.state[0] * s.length;
      out.time_of_max_overlap = hit.time * s.time;
    }
  }
  out.steps = result.steps;
  out.contact_time = followed_to_end ? options.follow_time : result.terminal.time * s.time;
  EnergyBudget& e = out.energy;
  e.initial_kinetic = s.energy;
  e.bulk_dissipated = end[2] * s.energy;
  e.crack_dissipated = snap_release;
  e.final_kinetic = s.energy * end[1] * end[1];
  if (result.hits.empty() && !followed_to_end) {  // stopped before the maximum compression
    out.max_overlap = std::max(end[0], 0.0) * s.length;
    out.time_of_max_overlap = result.terminal.time * s.time;
    out.notes.push_back(before_max_compression_note);
  }
  if (!followed_to_end && result.terminal.index == 1) {
    out.outcome = Outcome::bounce;
    out.cor = -end[1];
    // Release at the fold: a drops to 0 at delta_c, U_E + U_S there is dissipated.
    e.crack_dissipated += models::contact_energy(p, branch.radius(delta_c), delta_c);
  } else {
    out.outcome = Outcome::stick;
    out.cor = 0.0;
    const double delta = end[0] * s.length, a = branch.radius(delta);
    e.elastic_remaining = contact::independent::elastic_energy({p.effective_radius, p.effective_modulus}, a, delta);
    e.surface_remaining = contact::independent::surface_energy(a, p.surface_energy);
  }
  if (options.record_trajectory && !out.trajectory.empty() && out.outcome == Outcome::bounce) {
    out.trajectory.back().crack_dissipated = e.crack_dissipated;
  }
  e.close();
  return out;
}

}  // namespace bounce::dynamics

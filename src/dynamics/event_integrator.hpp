#pragma once
// Private: explicit Runge-Kutta integration with dense output and event location.
//
// Why Boost.Odeint's dopri5 (and not SUNDIALS) for non-stiff collision models:
// on the viscoelastic collision (2 variables) an odeint dopri5 step costs about
// 0.1 us, a CVODE step about 1.3 us (N_Vector overhead dominates for tiny systems),
// and CVODE's Adams/BDF need 2-4x more steps at equal accuracy because of the
// sqrt(xi) singularities at both ends of the contact (bench/bench_engines.cpp,
// docs/benchmarks.md). Stiff models (K13's crack) use the Rosenbrock engine of stiff.hpp.
//
// The integrator knows nothing about physics: a system is a callable
// f(y, dydt, t), events are scalar functions g(t, y) located on the dense output of
// the step in which they occur (event_locator.hpp); observers see every accepted step.

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <boost/numeric/odeint.hpp>
#include <fmt/format.h>

#include "bounce/dynamics/integration.hpp"
#include "event_locator.hpp"

namespace bounce::dynamics::detail {

template <std::size_t N>
using State = std::array<double, N>;

/// A scalar event function; `direction` -1: triggers when g falls through zero,
/// +1: when it rises, 0: either. Terminal events end the integration.
template <std::size_t N>
struct Event {
  int id = -1;  ///< what the caller calls it (an enum value); reported with every hit
  std::function<double(double t, const State<N>& y)> g;
  int direction = -1;
  bool terminal = true;
  bool armed = true;  ///< an unarmed event is skipped (armed by another event)
  int arms = -1;      ///< id of an event this one arms when it fires (-1: none)
  /// Also catch g touching zero inside a step without changing sign at its ends
  /// (event_locator.hpp): where the event is a threshold that a smooth peak may just reach
  /// (an asperity breaking at the top of its load); without it such an event is missed
  /// until the peak overshoots by the step's curvature (docs/tables.md).
  bool graze = false;
};

template <std::size_t N>
struct EventHit {
  int id = -1;  ///< which event (-1: none)
  double time = 0.0;
  State<N> state{};
};

template <std::size_t N>
struct IntegrationResult {
  EventHit<N> terminal;              ///< the terminal event that ended the run
  std::vector<EventHit<N>> hits;     ///< non-terminal events, in time order
  long steps = 0;
};

/// Called after every accepted step with the step interval and a function that
/// evaluates the dense output inside it.
template <std::size_t N>
using StepObserver = std::function<void(double t0, double t1, const std::function<State<N>(double)>& at)>;

/// The events of a run and where each one's current search window starts.
template <std::size_t N>
class EventWindows {
 public:
  EventWindows(std::vector<Event<N>>& events, double t0, const State<N>& y0)
      : events_(events), previous_(events.size()), start_(events.size(), t0) {
    for (std::size_t i = 0; i < events.size(); ++i) previous_[i] = events[i].g(t0, y0);
  }

  /// The earliest event firing in [ta, tb] (yb = y(tb), `at` the dense output): its index
  /// and time, or index -1.
  template <class At>
  std::pair<int, double> first(double ta, double tb, const State<N>& yb, const At& at) const {
    int first = -1;
    double first_time = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < events_.size(); ++i) {
      const Event<N>& e = events_[i];
      if (!e.armed) continue;
      const double ga = previous_[i], lo = std::max(ta, start_[i]);
      const auto g = [&](double t) { return t <= lo ? ga : e.g(t, at(t)); };
      const auto [a, b] = locate(g, lo, tb, ga, e.g(tb, yb), e.direction, e.graze);
      const double root = 0.5 * (a + b);
      if (root < first_time) {
        first_time = root;
        first = static_cast<int>(i);
      }
    }
    return {first, first_time};
  }

  /// Event `i` fired at `time` in state `y`: it arms the one it names there.
  void fire(std::size_t i, double time, const State<N>& y) {
    if (events_[i].arms < 0) return;
    for (std::size_t j = 0; j < events_.size(); ++j) {
      if (events_[j].id != events_[i].arms) continue;
      events_[j].armed = true;
      previous_[j] = events_[j].g(time, y);
      start_[j] = time;
    }
  }

  /// The step ended at tb: the armed events' windows start there.
  void advance(double tb, const State<N>& yb) {
    for (std::size_t i = 0; i < events_.size(); ++i) {
      if (events_[i].armed) {
        previous_[i] = events_[i].g(tb, yb);
        start_[i] = tb;
      }
    }
  }

 private:
  std::vector<Event<N>>& events_;
  std::vector<double> previous_;  // each event's value at the start of its window
  std::vector<double> start_;
};

template <std::size_t N>
void check_budget(long step, double t, const IntegrationSettings& settings) {
  if (step >= settings.max_steps) {
    throw StepBudgetExceeded(fmt::format(
        "integration stopped after {} steps at scaled time {:.6g} without reaching the end of contact", step, t));
  }
}

template <std::size_t N>
void check_finite(const State<N>& y, double t) {
  for (double v : y) {
    if (!std::isfinite(v)) throw NumericalError(fmt::format("state became non-finite at scaled time {:.6g}", t));
  }
}

template <std::size_t N, class System>
IntegrationResult<N> integrate_until_event(const System& system, const State<N>& y0, double t0,
                                           double initial_step, const IntegrationSettings& settings,
                                           std::vector<Event<N>>& events,
                                           const StepObserver<N>* observer = nullptr) {
  namespace odeint = boost::numeric::odeint;
  auto stepper = odeint::make_dense_output(settings.absolute_tolerance, settings.relative_tolerance,
                                           odeint::runge_kutta_dopri5<State<N>>());
  stepper.initialize(y0, t0, initial_step);
  EventWindows<N> windows(events, t0, y0);
  IntegrationResult<N> result;
  State<N> probe{};
  auto at = [&](double t) {
    stepper.calc_state(t, probe);
    return probe;
  };
  const std::function<State<N>(double)> dense = at;
  // odeint takes the system by value: a system that records its trajectory was copied with it at
  // every step, O(N^2) (a followed jkr-viscoelastic collision took 55 s for 1e-5 s; issue 40, 7).
  const auto rhs = [&system](const State<N>& y, State<N>& dydt, double t) { system(y, dydt, t); };
  for (long step = 0;; ++step) {
    check_budget<N>(step, stepper.current_time(), settings);
    const auto [ta, tb] = stepper.do_step(rhs);
    result.steps = step + 1;
    const State<N>& yb = stepper.current_state();
    check_finite<N>(yb, tb);
    // Handle the events of this step in time order (one may arm another).
    for (auto [i, time] = windows.first(ta, tb, yb, at); i >= 0; std::tie(i, time) = windows.first(ta, tb, yb, at)) {
      Event<N>& e = events[static_cast<std::size_t>(i)];
      const EventHit<N> hit{e.id, time, time >= tb ? yb : at(time)};
      windows.fire(static_cast<std::size_t>(i), time, hit.state);
      if (e.terminal) {
        if (observer) (*observer)(ta, time, dense);
        result.terminal = hit;
        return result;
      }
      result.hits.push_back(hit);
      e.armed = false;  // a non-terminal event fires once
    }
    windows.advance(tb, yb);
    if (observer) (*observer)(ta, tb, dense);
    if (tb > settings.max_time) {
      throw TimeBudgetExceeded(fmt::format("scaled time {:.6g} exceeds the budget {:.6g} without reaching the end of contact",
                                           tb, settings.max_time));
    }
  }
}

}  // namespace bounce::dynamics::detail

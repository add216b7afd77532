#pragma once
// Private: explicit Runge-Kutta integration with dense output and event location.
//
// Why Boost.Odeint's dopri5 (and not SUNDIALS) for non-stiff collision models:
// on the viscoelastic collision (2 variables) an odeint dopri5 step costs about
// 0.1 us, a CVODE step about 1.3 us (N_Vector overhead dominates for tiny systems),
// and CVODE's Adams/BDF need 2-4x more steps at equal accuracy because of the
// sqrt(xi) singularities at both ends of the contact (bench/bench_engines.cpp,
// docs/benchmarks.md). Stiff models (K13's crack) use CVODE instead.
//
// The integrator knows nothing about physics: a system is a callable
// f(y, dydt, t), events are scalar functions g(t, y) whose sign changes are
// located by root finding (TOMS 748) on the dense output of the step in which
// they occur; observers see every accepted step.

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint.hpp>
#include <fmt/format.h>

#include "bounce/dynamics/integration.hpp"

namespace bounce::dynamics::detail {

template <std::size_t N>
using State = std::array<double, N>;

/// A scalar event function; `direction` -1: triggers when g falls through zero,
/// +1: when it rises, 0: either. Terminal events end the integration.
template <std::size_t N>
struct Event {
  std::function<double(double t, const State<N>& y)> g;
  int direction = -1;
  bool terminal = true;
  bool armed = true;  ///< an unarmed event is skipped (armed by another event)
  int arms = -1;      ///< index of an event this one arms when it fires (-1: none)
  /// Also catch g touching zero inside a step without changing sign at its ends
  /// (direction -1: an interior minimum reaching 0; +1: a maximum). Needed where the
  /// event is a threshold that a smooth peak may just reach (an asperity breaking at
  /// the top of its load): without it such an event is missed until the peak overshoots
  /// by the step's curvature, so the outcome jumps late (docs/tables.md).
  bool graze = false;
};

/// The first point in [lo, hi] where g touches zero from the side `direction` leaves
/// (-1: g > 0 at both ends), or NaN when it does not. A parabola through the ends and
/// the midpoint says whether g has an interior extremum; only then is it located
/// (Brent) and, when it reaches zero, the root before it (TOMS 748).
template <class G>
double grazing_root(const G& g, double lo, double hi, double g_lo, double g_hi, int direction) {
  const double s = direction < 0 ? 1.0 : -1.0;  // minimise s g
  const double h = hi - lo, a = s * g_lo, b = s * g_hi, m = s * g(lo + 0.5 * h);
  const double curvature = 2.0 * (a - 2.0 * m + b) / (h * h), slope = (4.0 * m - 3.0 * a - b) / h;
  if (!(curvature > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double vertex = -slope / (2.0 * curvature);
  if (!(vertex > 0.0 && vertex < h)) return std::numeric_limits<double>::quiet_NaN();
  std::uintmax_t iterations = 100;
  const auto [t_min, g_min] =
      boost::math::tools::brent_find_minima([&](double t) { return s * g(t); }, lo, hi, 40, iterations);
  if (g_min > 0.0) return std::numeric_limits<double>::quiet_NaN();
  iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve([&](double t) { return s * g(t); }, lo, t_min, a, g_min,
                                                         boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (bracket.first + bracket.second);
}

template <std::size_t N>
struct EventHit {
  int index = -1;  ///< which event (-1: none)
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
using StepObserver =
    std::function<void(double t0, double t1, const std::function<State<N>(double)>& at)>;

template <std::size_t N, class System>
IntegrationResult<N> integrate_until_event(const System& system, const State<N>& y0, double t0,
                                           double initial_step, const IntegrationSettings& settings,
                                           std::vector<Event<N>>& events,
                                           const StepObserver<N>* observer = nullptr) {
  namespace odeint = boost::numeric::odeint;
  auto stepper = odeint::make_dense_output(settings.absolute_tolerance, settings.relative_tolerance,
                                           odeint::runge_kutta_dopri5<State<N>>());
  stepper.initialize(y0, t0, initial_step);
  // Value of each event function at the start of its current search window.
  std::vector<double> previous(events.size());
  std::vector<double> window_start(events.size(), t0);
  for (std::size_t i = 0; i < events.size(); ++i) previous[i] = events[i].g(t0, y0);

  IntegrationResult<N> result;
  State<N> probe{};
  auto at = [&](double t) {
    stepper.calc_state(t, probe);
    return probe;
  };
  const std::function<State<N>(double)> dense = at;

  for (long step = 0;; ++step) {
    if (step >= settings.max_steps) {
      throw StepBudgetExceeded(
          fmt::format("integration stopped after {} steps at scaled time {:.6g} without reaching "
                      "the end of contact",
                      step, stepper.current_time()));
    }
    const auto [ta, tb] = stepper.do_step(system);
    result.steps = step + 1;
    const State<N>& yb = stepper.current_state();
    for (double v : yb) {
      if (!std::isfinite(v)) {
        throw NumericalError(fmt::format("state became non-finite at scaled time {:.6g}", tb));
      }
    }
    // Locate every sign change in [ta, tb]; handle them in time order.
    for (;;) {
      int first = -1;
      double first_time = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < events.size(); ++i) {
        const Event<N>& e = events[i];
        if (!e.armed) continue;
        const double ga = previous[i];
        const double gb = e.g(tb, yb);
        const bool falls = ga > 0.0 && gb <= 0.0;
        const bool rises = ga < 0.0 && gb >= 0.0;
        if (!((e.direction <= 0 && falls) || (e.direction >= 0 && rises))) {
          const bool same_side = e.direction < 0 ? ga > 0.0 && gb > 0.0 : ga < 0.0 && gb < 0.0;
          if (e.graze && e.direction != 0 && same_side) {
            const double lo = std::max(ta, window_start[i]);
            const double root = grazing_root([&](double t) { return e.g(t, at(t)); }, lo, tb, ga, gb, e.direction);
            if (root < first_time) {
              first_time = root;
              first = static_cast<int>(i);
            }
          }
          continue;
        }
        // The root of g on the dense output, bracketed by [window start, tb].
        const double lo = std::max(ta, window_start[i]);
        auto f = [&](double t) { return t <= lo ? ga : e.g(t, at(t)); };
        std::uintmax_t iterations = 100;
        double root = tb;
        if (gb != 0.0) {
          const auto bracket = boost::math::tools::toms748_solve(
              f, lo, tb, ga, gb, boost::math::tools::eps_tolerance<double>(52), iterations);
          root = 0.5 * (bracket.first + bracket.second);
        }
        if (root < first_time) {
          first_time = root;
          first = static_cast<int>(i);
        }
      }
      if (first < 0) break;
      Event<N>& e = events[static_cast<std::size_t>(first)];
      EventHit<N> hit{first, first_time, first_time >= tb ? yb : at(first_time)};
      if (e.arms >= 0) {
        const auto j = static_cast<std::size_t>(e.arms);
        events[j].armed = true;
        previous[j] = events[j].g(first_time, hit.state);
        window_start[j] = first_time;
      }
      if (e.terminal) {
        if (observer) (*observer)(ta, first_time, dense);
        result.terminal = hit;
        return result;
      }
      result.hits.push_back(hit);
      e.armed = false;  // a non-terminal event fires once
    }
    for (std::size_t i = 0; i < events.size(); ++i) {
      if (events[i].armed) {
        previous[i] = events[i].g(tb, yb);
        window_start[i] = tb;
      }
    }
    if (observer) (*observer)(ta, tb, dense);
    if (tb > settings.max_time) {
      throw TimeBudgetExceeded(fmt::format(
          "scaled time {:.6g} exceeds the budget {:.6g} without reaching the end of contact", tb,
          settings.max_time));
    }
  }
}

}  // namespace bounce::dynamics::detail

#pragma once
// Settings and typed errors of the time integration (dynamics layer).
//
// The integrator itself (src/dynamics/event_integrator.hpp) is a private
// template over Boost.Odeint; the public API only sees these settings, the
// errors, and the outcome types of outcome.hpp.

#include <string>

#include "bounce/core/error.hpp"

namespace bounce::dynamics {

/// Tolerances and runaway guards. Times and states are in the scaled units of
/// each collision (overlap / xi0, rate / impact speed, time / (xi0 / speed)), so
/// the tolerances are dimensionless.
struct IntegrationSettings {
  double relative_tolerance = 1e-12;
  double absolute_tolerance = 1e-12;
  /// StepBudgetExceeded beyond this: ~0.5 s of steps. A collision takes 20-2000 steps; what
  /// needs more is creeping without end (a strongly overdamped contact), and 2e7 steps
  /// only made the refusal take 10-40 s.
  long max_steps = 2'000'000;
  double max_time = 1e9;         ///< scaled time budget: TimeBudgetExceeded beyond it
};

/// The engine of stiff models (docs/benchmarks.md): our RODAS (Rosenbrock, order 4,
/// the default: 2-3x faster than CVODE per K13 collision at equal accuracy on bounce's
/// small systems) or SUNDIALS CVODE (BDF; kept as the independent cross-check).
enum class StiffEngine { rodas, cvode };

/// The step budget ran out before the collision ended.
class StepBudgetExceeded : public NumericalError {
 public:
  explicit StepBudgetExceeded(const std::string& what) : NumericalError(what) {}
};

/// The (scaled) time budget ran out before the collision ended.
class TimeBudgetExceeded : public NumericalError {
 public:
  explicit TimeBudgetExceeded(const std::string& what) : NumericalError(what) {}
};

}  // namespace bounce::dynamics

#pragma once
// Private: stiff systems and their integrators.
//
// A stiff model (the K13 crack, whose relaxation can be 1e8 times faster than the
// collision) supplies its right-hand side, its analytic Jacobian (a finite-
// difference one is not enough there, docs/decisions.md D9) and its event functions. Two
// engines integrate it behind one interface:
//   - RODAS (rodas_integrator.hpp), our own fixed-size Rosenbrock method, the default;
//   - SUNDIALS CVODE (cvode_integrator.hpp), BDF with a dense direct solver.
// Why two, and why our own: docs/benchmarks.md. For a five-component system CVODE
// spends ~80% of its time in its generic vector layer (2.4 us per step against
// RODAS's ~0.5 us), and Boost.Odeint's rosenbrock4 (ublas) neither compiles as C++20
// nor runs faster (23 us per step). CVODE stays as the independent cross-check of
// the tests and as the reference of the benchmark.

#include <memory>
#include <vector>

#include "bounce/dynamics/integration.hpp"

namespace bounce::dynamics::detail {

class StiffSystem {
 public:
  virtual ~StiffSystem() = default;
  virtual int size() const = 0;
  /// 0: success; > 0: recoverable (the trial state is outside the model's domain,
  /// the engine retries with a smaller step); < 0: unrecoverable.
  virtual int rhs(double t, const double* y, double* dydt) const = 0;
  /// Row-major Jacobian j[i * n + k] = d f_i / d y_k and, unless dfdt is null, the
  /// explicit time derivative d f_i / d t (Rosenbrock methods need it); same
  /// return convention.
  virtual int jacobian(double t, const double* y, double* j, double* dfdt) const = 0;
  /// rhs, jacobian and, unless g is null, the events at one point, in one call: a system
  /// whose three share costly work (K13's crack law and effective surface energy) does it
  /// once. Same return convention; on a nonzero return g is undefined.
  virtual int linearize(double t, const double* y, double* f, double* j, double* dfdt, double* g) const {
    int flag = rhs(t, y, f);
    if (flag == 0) flag = jacobian(t, y, j, dfdt);
    if (flag == 0 && g != nullptr) events(t, y, g);
    return flag;
  }
  /// The components that enter no right-hand side (zero Jacobian columns), bit i for
  /// component i: quadratures (K13's dissipated energies) and the time of a swapped autonomous
  /// system. The iteration matrix is then block triangular, and the Rosenbrock engine
  /// factorizes the block of the other components alone and gets these from it (exact).
  virtual unsigned quadratures() const { return 0; }
  virtual int event_count() const = 0;
  virtual void events(double t, const double* y, double* g) const = 0;
};

/// An autonomous system with one component as the independent variable: with
/// s = sign * y[index] (sign +1 or -1, chosen so that s increases) the state holds
/// the time in place of y[index], and
///   dz_i/ds = sign f_i / f_index (i != index),   dt/ds = sign / f_index.
/// For a component that runs away (f_index -> infinity, a crack reaching a
/// singularity of its speed law) the swapped system is smooth where the original
/// needs tens of steps per decade of the distance to the singular time.
class SwappedIndependent final : public StiffSystem {
 public:
  SwappedIndependent(const StiffSystem& inner, int index, double sign);
  /// The original state y at s.
  std::vector<double> original(double s, const double* z) const;
  int size() const override { return inner_.size(); }
  int rhs(double s, const double* z, double* dzds) const override;
  int jacobian(double s, const double* z, double* j, double* dfds) const override;
  int linearize(double s, const double* z, double* f, double* j, double* dfds, double* g) const override;
  /// The inner system's quadratures and the time (the inner system is autonomous).
  unsigned quadratures() const override { return inner_.quadratures() | (1u << index_); }
  int event_count() const override { return inner_.event_count(); }
  void events(double s, const double* z, double* g) const override;

 private:
  const StiffSystem& inner_;
  int index_;
  double sign_;
};

struct StiffSettings {
  double relative_tolerance = 1e-10;
  std::vector<double> absolute_tolerance;  ///< one per component
  long max_steps = 5'000'000;
  double max_time = 1e12;                  ///< TimeBudgetExceeded when a step reaches it
  double initial_step = 0.0;               ///< 0: the engine's own estimate
  std::vector<int> event_directions;       ///< -1 falling, +1 rising, 0 both
};

class StiffIntegrator {
 public:
  virtual ~StiffIntegrator() = default;
  struct Step {
    double t0 = 0.0;              ///< start of the step
    double t1 = 0.0;              ///< end of the step (the event time if one fired)
    std::vector<int> fired;       ///< indices of the events found at t1
  };
  /// One step, stopping at the first event inside it. Throws StepBudgetExceeded,
  /// TimeBudgetExceeded or NumericalError.
  virtual Step step() = 0;
  /// The current state (at the end of the last step).
  virtual std::vector<double> state() const = 0;
  /// The dense output inside the last step.
  virtual std::vector<double> state_at(double t) const = 0;
  virtual long steps() const = 0;
  /// Switch an event off (e.g. a maximum-compression event that fires once).
  virtual void disable_event(int index) = 0;
};

std::unique_ptr<StiffIntegrator> make_stiff_integrator(StiffEngine engine, const StiffSystem& system,
                                                       const std::vector<double>& y0, double t0,
                                                       const StiffSettings& settings);

}  // namespace bounce::dynamics::detail

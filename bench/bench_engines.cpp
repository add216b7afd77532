// Why the non-stiff collision models integrate with Boost.Odeint's dopri5 and not
// SUNDIALS: the scaled viscoelastic collision (BP04 (8.67)) integrated by
//   * bounce's engine (odeint dopri5, dense output, events by TOMS 748),
//   * CVODE Adams (orders 1-12) and CVODE BDF (orders 1-5, analytic Jacobian),
//     with CVODE's own root finding for the end of contact,
// at several tolerances; the error against the master curve is a counter, so
// time can be compared at equal accuracy (docs/benchmarks.md).
#include <cmath>

#include <benchmark/benchmark.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "bounce/analytic/master_curve.hpp"
#include "unit_collision.hpp"

namespace {

int rhs(sunrealtype, N_Vector y, N_Vector dydt, void* data) {
  const double kappa = *static_cast<double*>(data);
  const double* s = N_VGetArrayPointer(y);
  double* d = N_VGetArrayPointer(dydt);
  const double root = std::sqrt(std::max(s[0], 0.0));
  d[0] = s[1];
  d[1] = -1.25 * s[0] * root - kappa * root * s[1];
  return 0;
}

int jacobian(sunrealtype, N_Vector y, N_Vector, SUNMatrix j, void* data, N_Vector, N_Vector, N_Vector) {
  const double kappa = *static_cast<double*>(data);
  const double* s = N_VGetArrayPointer(y);
  const double root = std::sqrt(std::max(s[0], 1e-300));
  SM_ELEMENT_D(j, 0, 0) = 0.0;
  SM_ELEMENT_D(j, 0, 1) = 1.0;
  SM_ELEMENT_D(j, 1, 0) = s[0] > 0.0 ? -1.875 * root - 0.5 * kappa * s[1] / root : 0.0;
  SM_ELEMENT_D(j, 1, 1) = -kappa * root;
  return 0;
}

int overlap_root(sunrealtype, N_Vector y, sunrealtype* g, void*) {
  g[0] = N_VGetArrayPointer(y)[0];
  return 0;
}

double cvode_cor(double kappa, double tolerance, int method, long& steps) {
  SUNContext context;
  SUNContext_Create(nullptr, &context);
  N_Vector y = N_VNew_Serial(2, context);
  N_VGetArrayPointer(y)[0] = 0.0;
  N_VGetArrayPointer(y)[1] = 1.0;
  void* memory = CVodeCreate(method, context);
  CVodeInit(memory, rhs, 0.0, y);
  CVodeSStolerances(memory, tolerance, tolerance);
  CVodeSetUserData(memory, &kappa);
  SUNMatrix a = SUNDenseMatrix(2, 2, context);
  SUNLinearSolver solver = SUNLinSol_Dense(y, a, context);
  CVodeSetLinearSolver(memory, solver, a);
  CVodeSetJacFn(memory, jacobian);
  CVodeSetMaxNumSteps(memory, 10'000'000);
  CVodeRootInit(memory, 1, overlap_root);
  int direction = -1;
  CVodeSetRootDirection(memory, &direction);
  CVodeSetNoInactiveRootWarn(memory);
  double t = 0.0, e = -1.0;
  for (;;) {
    const int flag = CVode(memory, 1e6, y, &t, CV_ONE_STEP);
    if (flag == CV_ROOT_RETURN) {
      e = -N_VGetArrayPointer(y)[1];
      break;
    }
    if (flag < 0) break;
  }
  long n = 0;
  CVodeGetNumSteps(memory, &n);
  steps = n;
  CVodeFree(&memory);
  SUNLinSolFree(solver);
  SUNMatDestroy(a);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return e;
}

void cvode(benchmark::State& state, int method) {
  const double kappa = 0.3, tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  double e = 0.0;
  long steps = 0;
  for (auto _ : state) e = cvode_cor(kappa, tolerance, method, steps);
  state.counters["error"] = std::abs(e - bounce::analytic::master_cor(kappa, bounce::models::EndRule::overlap));
  state.counters["steps"] = static_cast<double>(steps);
}

void odeint(benchmark::State& state) {
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  bounce::dynamics::NormalCollisionOptions options;
  options.integration.relative_tolerance = tolerance;
  options.integration.absolute_tolerance = tolerance;
  bench::time_unit_collision(state, 0.3, options);
}

}  // namespace

BENCHMARK(odeint)->DenseRange(8, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(cvode, adams, CV_ADAMS)->DenseRange(8, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(cvode, bdf, CV_BDF)->DenseRange(8, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();

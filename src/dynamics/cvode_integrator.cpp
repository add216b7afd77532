#include "cvode_integrator.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>

#include <fmt/format.h>

namespace bounce::dynamics::detail {

struct CvodeIntegrator::Impl {
  const StiffSystem* system = nullptr;
  StiffSettings settings;
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  N_Vector atol = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  void* memory = nullptr;
  double t = 0.0;
  long steps = 0;
  std::vector<bool> enabled;
  std::string last_error;

  static int rhs(sunrealtype t, N_Vector y, N_Vector dydt, void* data) {
    const auto* self = static_cast<Impl*>(data);
    return self->system->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(dydt));
  }
  static int jacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix j, void* data, N_Vector, N_Vector,
                      N_Vector) {
    const auto* self = static_cast<Impl*>(data);
    const int n = self->system->size();
    std::vector<double> row_major(static_cast<std::size_t>(n * n));
    const int flag = self->system->jacobian(t, N_VGetArrayPointer(y), row_major.data(), nullptr);
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) SM_ELEMENT_D(j, r, c) = row_major[static_cast<std::size_t>(r * n + c)];
    }
    return flag;
  }
  static int roots(sunrealtype t, N_Vector y, sunrealtype* g, void* data) {
    auto* self = static_cast<Impl*>(data);
    self->system->events(t, N_VGetArrayPointer(y), g);
    for (std::size_t i = 0; i < self->enabled.size(); ++i) {
      if (!self->enabled[i]) g[i] = 1.0;  // a constant, never a root
    }
    return 0;
  }
  // CVODE's error text, kept for the exception: SUNDIALS 7's context handler stack
  // (cmake/BounceSundials.cmake tells which API compiles) or SUNDIALS 6's CVODE handler.
#if BOUNCE_SUNDIALS_PUSH_ERR_HANDLER
  static void error_handler(int, const char* function, const char*, const char* message, SUNErrCode code,
                            void* data, SUNContext) {
    static_cast<Impl*>(data)->last_error = fmt::format("{} ({}): {}", function, code, message);
  }
  void install_error_handler() {
    // The default handler prints to stderr; ours only keeps the text for the exception.
    if (SUNContext_ClearErrHandlers(context) != SUN_SUCCESS ||
        SUNContext_PushErrHandler(context, &Impl::error_handler, this) != SUN_SUCCESS) {
      throw NumericalError("SUNDIALS error handler could not be installed");
    }
  }
#else
  static void error_handler(int, const char* module, const char* function, char* message, void* data) {
    static_cast<Impl*>(data)->last_error = fmt::format("{} {}: {}", module, function, message);
  }
  void install_error_handler() { CVodeSetErrHandlerFn(memory, &Impl::error_handler, this); }
#endif

  void check(int flag, const char* what) const {
    if (flag < 0) throw NumericalError(fmt::format("CVODE {} failed ({}): {}", what, flag, last_error));
  }

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  // Every SUNDIALS handle is freed here, also when the integrator's constructor throws
  // half-way (impl_ is then destroyed as a finished member).
  ~Impl() {
    if (memory) CVodeFree(&memory);
    if (solver) SUNLinSolFree(solver);
    if (matrix) SUNMatDestroy(matrix);
    if (y) N_VDestroy(y);
    if (atol) N_VDestroy(atol);
    if (context) SUNContext_Free(&context);
  }
};

CvodeIntegrator::CvodeIntegrator(const StiffSystem& system, const std::vector<double>& y0, double t0,
                                 const StiffSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.system = &system;
  m.settings = settings;
  m.t = t0;
  const int n = system.size();
  m.enabled.assign(static_cast<std::size_t>(system.event_count()), true);
#if BOUNCE_SUNDIALS_COMM_NULL
  if (SUNContext_Create(SUN_COMM_NULL, &m.context) != 0) throw NumericalError("SUNDIALS context creation failed");
#else
  if (SUNContext_Create(nullptr, &m.context) != 0) throw NumericalError("SUNDIALS context creation failed");
#endif
  m.y = N_VNew_Serial(n, m.context);
  N_VEnableFusedOps_Serial(m.y, SUNTRUE);  // fewer calls per step: a 5-vector is all overhead
  m.atol = N_VNew_Serial(n, m.context);
  for (int i = 0; i < n; ++i) {
    N_VGetArrayPointer(m.y)[i] = y0[static_cast<std::size_t>(i)];
    N_VGetArrayPointer(m.atol)[i] = settings.absolute_tolerance.at(static_cast<std::size_t>(i));
  }
  m.memory = CVodeCreate(CV_BDF, m.context);
  if (m.memory == nullptr) throw NumericalError("CVodeCreate failed");
  m.install_error_handler();
  // No "t + h = t" warnings: SUNDIALS 7's default logger would print them on stdout; a step
  // too small for the time's resolution ends in an error (or our step budget) all the same.
  m.check(CVodeSetMaxHnilWarns(m.memory, -1), "warnings");
  m.check(CVodeInit(m.memory, &Impl::rhs, t0, m.y), "init");
  m.check(CVodeSVtolerances(m.memory, settings.relative_tolerance, m.atol), "tolerances");
  m.check(CVodeSetUserData(m.memory, &m), "user data");
  m.matrix = SUNDenseMatrix(n, n, m.context);
  m.solver = SUNLinSol_Dense(m.y, m.matrix, m.context);
  m.check(CVodeSetLinearSolver(m.memory, m.solver, m.matrix), "linear solver");
  m.check(CVodeSetJacFn(m.memory, &Impl::jacobian), "Jacobian");
  m.check(CVodeSetMaxNumSteps(m.memory, -1), "step limit");  // our own budget below
  m.check(CVodeSetMaxErrTestFails(m.memory, 50), "error-test failures");
  m.check(CVodeSetMaxConvFails(m.memory, 50), "convergence failures");
  if (settings.initial_step > 0.0) m.check(CVodeSetInitStep(m.memory, settings.initial_step), "initial step");
  if (system.event_count() > 0) {
    m.check(CVodeRootInit(m.memory, system.event_count(), &Impl::roots), "events");
    std::vector<int> directions = settings.event_directions;
    directions.resize(static_cast<std::size_t>(system.event_count()), 0);
    m.check(CVodeSetRootDirection(m.memory, directions.data()), "event directions");
    CVodeSetNoInactiveRootWarn(m.memory);
  }
}

CvodeIntegrator::~CvodeIntegrator() = default;

StiffIntegrator::Step CvodeIntegrator::step() {
  Impl& m = *impl_;
  if (m.steps >= m.settings.max_steps) {
    throw StepBudgetExceeded(fmt::format("stiff integration stopped after {} steps at scaled time {:.6g}",
                                         m.steps, m.t));
  }
  Step s;
  s.t0 = m.t;
  double t = m.t;
  const int flag = CVode(m.memory, m.settings.max_time, m.y, &t, CV_ONE_STEP);
  ++m.steps;
  if (flag < 0) {
    throw NumericalError(fmt::format("CVODE step failed at scaled time {:.6g} ({}): {}", m.t, flag,
                                     m.last_error));
  }
  m.t = t;
  s.t1 = t;
  for (int i = 0; i < impl_->system->size(); ++i) {
    if (!std::isfinite(N_VGetArrayPointer(m.y)[i])) {
      throw NumericalError(fmt::format("state became non-finite at scaled time {:.6g}", t));
    }
  }
  if (flag == CV_ROOT_RETURN) {
    std::vector<int> info(m.enabled.size());
    CVodeGetRootInfo(m.memory, info.data());
    for (std::size_t i = 0; i < info.size(); ++i) {
      if (info[i] != 0 && m.enabled[i]) s.fired.push_back(static_cast<int>(i));
    }
  }
  if (t >= m.settings.max_time) {
    throw TimeBudgetExceeded(fmt::format("scaled time {:.6g} exceeds the budget {:.6g}", t, m.settings.max_time));
  }
  return s;
}

std::vector<double> CvodeIntegrator::state() const {
  const int n = impl_->system->size();
  const double* p = N_VGetArrayPointer(impl_->y);
  return std::vector<double>(p, p + n);
}

std::vector<double> CvodeIntegrator::state_at(double t) const {
  const int n = impl_->system->size();
  N_Vector out = N_VNew_Serial(n, impl_->context);
  const int flag = CVodeGetDky(impl_->memory, t, 0, out);
  std::vector<double> y(N_VGetArrayPointer(out), N_VGetArrayPointer(out) + n);
  N_VDestroy(out);
  if (flag < 0) return state();
  return y;
}

long CvodeIntegrator::steps() const { return impl_->steps; }

void CvodeIntegrator::disable_event(int index) { impl_->enabled.at(static_cast<std::size_t>(index)) = false; }

}  // namespace bounce::dynamics::detail

#include "rodas_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "event_locator.hpp"

namespace bounce::dynamics::detail {

namespace {

// RODAS in the transformed form of Hairer & Wanner (IV.7.25): stage i solves
//   (I/(gamma h) - J) g_i = f(t + c_i h, y + sum a_ij g_j) + d_i h f_t + sum c_ij g_j / h,
// the solution is y + sum a_5j g_j + g_5 + g_6 and g_6 the error estimate.
// Coefficients of Hairer's rodas.f (method 1). Boost.Odeint's default_rosenbrock_coefficients
// has the same values but d4 = +0.0362 (rodas.f: -0.0362); d_i multiplies only f_t, which
// is zero for bounce's autonomous systems, so the sign does not show in its results.
struct Coefficients {
  static constexpr double gamma = 0.25;
  static constexpr double d1 = 0.25, d2 = -0.1043, d3 = 0.1035, d4 = -0.3620000000000023e-01;
  static constexpr double c2 = 0.386, c3 = 0.21, c4 = 0.63;
  static constexpr double c21 = -0.5668800000000000e+01, a21 = 0.1544000000000000e+01;
  static constexpr double c31 = -0.2430093356833875e+01, c32 = -0.2063599157091915e+00;
  static constexpr double a31 = 0.9466785280815826e+00, a32 = 0.2557011698983284e+00;
  static constexpr double c41 = -0.1073529058151375e+00, c42 = -0.9594562251023355e+01, c43 = -0.2047028614809616e+02;
  static constexpr double a41 = 0.3314825187068521e+01, a42 = 0.2896124015972201e+01, a43 = 0.9986419139977817e+00;
  static constexpr double c51 = 0.7496443313967647e+01, c52 = -0.1024680431464352e+02, c53 = -0.3399990352819905e+02,
                          c54 = 0.1170890893206160e+02;
  static constexpr double a51 = 0.1221224509226641e+01, a52 = 0.6019134481288629e+01, a53 = 0.1253708332932087e+02,
                          a54 = -0.6878860361058950e+00;
  static constexpr double c61 = 0.8083246795921522e+01, c62 = -0.7981132988064893e+01, c63 = -0.3152159432874371e+02,
                          c64 = 0.1631930543123136e+02, c65 = -0.6058818238834054e+01;
  // Dense output (order 3).
  static constexpr double d21 = 0.1012623508344586e+02, d22 = -0.7487995877610167e+01, d23 = -0.3480091861555747e+02,
                          d24 = -0.7992771707568823e+01, d25 = 0.1025137723295662e+01;
  static constexpr double d31 = -0.6762803392801253e+00, d32 = 0.6087714651680015e+01, d33 = 0.1643084320892478e+02,
                          d34 = 0.2476722511418386e+02, d35 = -0.6594389125716872e+01;
};
using C = Coefficients;

// LU decomposition with partial pivoting of the N x N row-major matrix a (in place):
// P A = L U, whole rows swapped; the diagonal of U is stored inverted. N is a
// compile-time constant so that the loops unroll (a 5 x 5 solve is otherwise
// dominated by loop overhead and division latency).
template <int N>
bool lu_factorize(double* a, int* pivot) {
  for (int k = 0; k < N; ++k) {
    int p = k;
    for (int i = k + 1; i < N; ++i) {
      if (std::abs(a[i * N + k]) > std::abs(a[p * N + k])) p = i;
    }
    pivot[k] = p;
    if (a[p * N + k] == 0.0 || !std::isfinite(a[p * N + k])) return false;
    if (p != k) {
      for (int j = 0; j < N; ++j) std::swap(a[k * N + j], a[p * N + j]);
    }
    const double inverse = a[k * N + k] = 1.0 / a[k * N + k];
    for (int i = k + 1; i < N; ++i) {
      const double factor = a[i * N + k] *= inverse;
      for (int j = k + 1; j < N; ++j) a[i * N + j] -= factor * a[k * N + j];
    }
  }
  return true;
}

// Solves A x = b in place: the permutation applies to b first, then L and U.
template <int N>
void lu_solve(const double* a, const int* pivot, double* b) {
  for (int k = 0; k < N; ++k) {
    if (pivot[k] != k) std::swap(b[k], b[pivot[k]]);
  }
  for (int k = 0; k < N; ++k) {
    for (int i = k + 1; i < N; ++i) b[i] -= a[i * N + k] * b[k];
  }
  for (int k = N - 1; k >= 0; --k) {
    for (int j = k + 1; j < N; ++j) b[k] -= a[k * N + j] * b[j];
    b[k] *= a[k * N + k];
  }
}

using Factorize = bool (*)(double*, int*);
using Solve = void (*)(const double*, const int*, double*);
template <int... Sizes>
std::pair<Factorize, Solve> linear_algebra(int n, std::integer_sequence<int, Sizes...>) {
  std::pair<Factorize, Solve> out{nullptr, nullptr};
  (void)((n == Sizes + 1 ? (out = {&lu_factorize<Sizes + 1>, &lu_solve<Sizes + 1>}, true) : false) || ...);  // clang: -Wunused-value
  return out;
}

}  // namespace

RodasIntegrator::RodasIntegrator(const StiffSystem& system, const std::vector<double>& y0, double t0,
                                 const StiffSettings& settings)
    : system_(system), settings_(settings), n_(system.size()), t_(t0), t_old_(t0), t_new_(t0) {
  if (n_ < 1 || n_ > capacity) throw NumericalError(fmt::format("RODAS: {} components, 1 to {} allowed", n_, capacity));
  // The trailing run of quadratures is solved from the coupled block before it (a quadrature
  // among the coupled components is just treated as one of them).
  const unsigned quadratures = system.quadratures();
  m_ = n_;
  while (m_ > 1 && ((quadratures >> (m_ - 1)) & 1u)) --m_;
  std::tie(factorize_, solve_) = linear_algebra(m_, std::make_integer_sequence<int, capacity>{});
  for (int i = 0; i < n_; ++i) y_[i] = y0.at(static_cast<std::size_t>(i));
  y_old_ = y_new_ = y_;
  settings_.absolute_tolerance.resize(static_cast<std::size_t>(n_), settings.relative_tolerance);
  if (system.event_count() > max_events) throw NumericalError("RODAS: too many events");
  settings_.event_directions.resize(static_cast<std::size_t>(system.event_count()), 0);
  enabled_.assign(static_cast<std::size_t>(system.event_count()), true);
  g_ = events_at(t_, y_);
  h_ = settings.initial_step > 0.0 ? settings.initial_step : initial_step();
}

RodasIntegrator::Events RodasIntegrator::events_at(double t, const Vec& y) const {
  Events g{};
  if (system_.event_count() > 0) system_.events(t, y.data(), g.data());
  return g;
}

double RodasIntegrator::error_norm(const Vec& y_new, const Vec& error) const {  // weighted RMS
  double sum = 0.0;
  for (int i = 0; i < n_; ++i) {
    const double scale = settings_.absolute_tolerance[static_cast<std::size_t>(i)] +
                         settings_.relative_tolerance * std::max(std::abs(y_[i]), std::abs(y_new[i]));
    sum += (error[i] / scale) * (error[i] / scale);
  }
  return std::sqrt(sum / n_);
}

// Hairer, Norsett & Wanner, Solving ODEs I, II.4 (starting step size), for order 4.
double RodasIntegrator::initial_step() {
  Vec f0{}, f1{}, y1{};
  if (system_.rhs(t_, y_.data(), f0.data()) != 0) throw NumericalError("RODAS: the initial state is outside the domain");
  double norm_y = 0.0, norm_f = 0.0;
  for (int i = 0; i < n_; ++i) {
    const double scale = settings_.absolute_tolerance[static_cast<std::size_t>(i)] +
                         settings_.relative_tolerance * std::abs(y_[i]);
    norm_y += (y_[i] / scale) * (y_[i] / scale);
    norm_f += (f0[i] / scale) * (f0[i] / scale);
  }
  norm_y = std::sqrt(norm_y / n_);
  norm_f = std::sqrt(norm_f / n_);
  double h0 = norm_y < 1e-5 || norm_f < 1e-5 ? 1e-6 : 0.01 * norm_y / norm_f;
  for (int i = 0; i < n_; ++i) y1[i] = y_[i] + h0 * f0[i];
  if (system_.rhs(t_ + h0, y1.data(), f1.data()) != 0) return 1e-3 * h0;
  double norm_d2 = 0.0;
  for (int i = 0; i < n_; ++i) {
    const double scale = settings_.absolute_tolerance[static_cast<std::size_t>(i)] +
                         settings_.relative_tolerance * std::abs(y_[i]);
    norm_d2 += ((f1[i] - f0[i]) / scale) * ((f1[i] - f0[i]) / scale);
  }
  norm_d2 = std::sqrt(norm_d2 / n_) / h0;
  const double larger = std::max(norm_f, norm_d2);
  const double h1 = larger <= 1e-15 ? std::max(1e-6, 1e-3 * h0) : std::pow(0.01 / larger, 0.2);
  return std::min(100.0 * h0, h1);
}

bool RodasIntegrator::linearize() {
  if (linearized_) return true;
  const int flag = system_.linearize(t_, y_.data(), f0_.data(), jacobian_.data(), dfdt_.data(), nullptr);
  if (flag < 0) throw NumericalError("RODAS: unrecoverable failure of the right-hand side");
  linearized_ = flag == 0;
  return linearized_;
}

// Solves (I/(gamma h) - J) g = b in place: the LU of the coupled block, then each trailing
// quadrature q from its row, g_q = gamma h (b_q + sum_k J_qk g_k) (J_qq' = 0).
void RodasIntegrator::solve(Vec& g, double gamma_h) const {
  solve_(lu_.data(), pivot_.data(), g.data());
  for (int q = m_; q < n_; ++q) {
    double sum = g[static_cast<std::size_t>(q)];
    for (int k = 0; k < m_; ++k) sum += jacobian_[static_cast<std::size_t>(q * n_ + k)] * g[static_cast<std::size_t>(k)];
    g[static_cast<std::size_t>(q)] = gamma_h * sum;
  }
}

bool RodasIntegrator::attempt(double h, Vec& y_new, Vec& error) {
  const int n = n_, m = m_;
  Vec f{}, x{};
  auto fail = [](int flag) {
    if (flag < 0) throw NumericalError("RODAS: unrecoverable failure of the right-hand side");
    return flag != 0;
  };
  if (!linearize()) return false;
  const Vec& dfdt = dfdt_;
  const double gh = C::gamma * h, inv_h = 1.0 / h;
  for (int i = 0; i < m; ++i) {
    for (int k = 0; k < m; ++k) lu_[static_cast<std::size_t>(i * m + k)] = -jacobian_[static_cast<std::size_t>(i * n + k)];
    lu_[static_cast<std::size_t>(i * m + i)] += 1.0 / gh;
  }
  if (!factorize_(lu_.data(), pivot_.data())) return false;
  auto& [g1, g2, g3, g4, g5] = stages_;
  for (int i = 0; i < n; ++i) g1[i] = f0_[i] + h * C::d1 * dfdt[i];
  solve(g1, gh);

  for (int i = 0; i < n; ++i) x[i] = y_[i] + C::a21 * g1[i];
  if (fail(system_.rhs(t_ + C::c2 * h, x.data(), f.data()))) return false;
  for (int i = 0; i < n; ++i) g2[i] = f[i] + h * C::d2 * dfdt[i] + C::c21 * g1[i] * inv_h;
  solve(g2, gh);

  for (int i = 0; i < n; ++i) x[i] = y_[i] + C::a31 * g1[i] + C::a32 * g2[i];
  if (fail(system_.rhs(t_ + C::c3 * h, x.data(), f.data()))) return false;
  for (int i = 0; i < n; ++i) g3[i] = f[i] + h * C::d3 * dfdt[i] + (C::c31 * g1[i] + C::c32 * g2[i]) * inv_h;
  solve(g3, gh);

  for (int i = 0; i < n; ++i) x[i] = y_[i] + C::a41 * g1[i] + C::a42 * g2[i] + C::a43 * g3[i];
  if (fail(system_.rhs(t_ + C::c4 * h, x.data(), f.data()))) return false;
  for (int i = 0; i < n; ++i) g4[i] = f[i] + h * C::d4 * dfdt[i] + (C::c41 * g1[i] + C::c42 * g2[i] + C::c43 * g3[i]) * inv_h;
  solve(g4, gh);

  for (int i = 0; i < n; ++i) x[i] = y_[i] + C::a51 * g1[i] + C::a52 * g2[i] + C::a53 * g3[i] + C::a54 * g4[i];
  if (fail(system_.rhs(t_ + h, x.data(), f.data()))) return false;
  for (int i = 0; i < n; ++i) g5[i] = f[i] + (C::c51 * g1[i] + C::c52 * g2[i] + C::c53 * g3[i] + C::c54 * g4[i]) * inv_h;
  solve(g5, gh);

  for (int i = 0; i < n; ++i) x[i] += g5[i];
  if (fail(system_.rhs(t_ + h, x.data(), f.data()))) return false;
  for (int i = 0; i < n; ++i) {
    error[i] = f[i] + (C::c61 * g1[i] + C::c62 * g2[i] + C::c63 * g3[i] + C::c64 * g4[i] + C::c65 * g5[i]) * inv_h;
  }
  solve(error, gh);
  bool finite = true;
  for (int i = 0; i < n; ++i) {
    y_new[i] = x[i] + error[i];
    finite = finite && std::isfinite(y_new[i]);
  }
  return finite;
}

// One accepted step from (t_, y_) (step-size control of Hairer & Wanner IV (8.21) with
// Gustafsson's predictive controller): its size, and the new state in y_new.
double RodasIntegrator::accepted_step(Vec& y_new) {
  constexpr double safety = 0.9, max_shrink = 5.0, max_growth = 1.0 / 6.0;  // fac1, fac2 of (8.21)
  Vec error{};
  int failures = 0;
  double h = std::min(h_, settings_.max_time - t_);
  for (;;) {
    if (!(h > 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t_), 1e-300)) || failures > 200) {
      throw NumericalError(fmt::format("RODAS: step size underflow at scaled time {:.6g} (h = {:.3g}, state {:.6g}, {} failures)",
                                       t_, h, fmt::join(y_.begin(), y_.begin() + n_, ", "), failures));
    }
    const bool inside = attempt(h, y_new, error);
    const double err = inside ? error_norm(y_new, error) : HUGE_VAL;
    if (!std::isfinite(err)) {  // outside the domain or no error estimate: a much smaller step
      ++failures;
      h *= 0.25;
      last_rejected_ = true;
      continue;
    }
    double factor = std::clamp(std::sqrt(std::sqrt(err)) / safety, max_growth, max_shrink);  // err^(1/4)
    if (err <= 1.0) {
      if (!first_step_) {  // Gustafsson's predictive controller
        const double predicted = (h_old_ / h) * std::sqrt(std::sqrt(err * err / error_old_)) / safety;
        factor = std::max(factor, std::clamp(predicted, max_growth, max_shrink));
      }
      first_step_ = false;
      h_old_ = h;
      error_old_ = std::max(0.01, err);
      double h_next = h / factor;
      if (last_rejected_) h_next = std::min(h_next, h);
      last_rejected_ = false;
      h_ = h_next;
      return h;
    }
    ++failures;
    h /= factor;
    last_rejected_ = true;
  }
}

// The events that fire in the last step [t_old_, t_new_], located on the dense output
// (event_locator.hpp) just past their crossing (so that they cannot fire again): the
// earliest and every one within round-off of it.
std::vector<int> RodasIntegrator::fired(const Events& g, double& first) const {
  std::vector<std::pair<int, double>> roots;
  first = t_new_;
  for (std::size_t i = 0; i < enabled_.size(); ++i) {
    if (!enabled_[i]) continue;
    auto gi = [&](double t) { return events_at(t, interpolate(t))[i]; };
    const auto [lo, hi] = locate(gi, t_old_, t_new_, g_[i], g[i], settings_.event_directions[i], false);
    if (std::isnan(hi)) continue;
    roots.emplace_back(static_cast<int>(i), hi);
    first = std::min(first, hi);
  }
  std::vector<int> out;
  const double close = 8.0 * std::numeric_limits<double>::epsilon() * (std::abs(first) + std::abs(h_old_));
  for (const auto& [index, root] : roots) {
    if (root <= first + close) out.push_back(index);
  }
  return out;
}

// Step again, exactly to the event at `first`: the order-3 dense output is less accurate
// than the order-4 step (an energy budget closed on interpolated states showed it). The
// fired events are on their far side there by construction.
RodasIntegrator::Events RodasIntegrator::step_to_event(double first, const std::vector<int>& fired) {
  t_ = t_old_;
  y_ = y_old_;
  linearized_ = false;
  Vec y_event{}, unused{};
  if (first < t_new_ && first > t_old_ && attempt(first - t_old_, y_event, unused)) {
    dense_output();
    t_new_ = first;
    y_new_ = y_ = y_event;
  } else {
    y_ = interpolate(first);
  }
  t_ = first;
  linearized_ = false;
  Events g = events_at(t_, y_);
  for (int index : fired) {
    const int dir = settings_.event_directions[static_cast<std::size_t>(index)];
    double& value = g[static_cast<std::size_t>(index)];
    if (dir < 0 && value > 0.0) value = 0.0;
    if (dir > 0 && value < 0.0) value = 0.0;
  }
  return g;
}

StiffIntegrator::Step RodasIntegrator::step() {
  if (steps_ >= settings_.max_steps) {
    throw StepBudgetExceeded(fmt::format("stiff integration stopped after {} steps at scaled time {:.6g}", steps_, t_));
  }
  Vec y_new{};
  const double h = accepted_step(y_new);
  ++steps_;
  dense_output();
  t_old_ = t_;
  y_old_ = y_;
  t_new_ = t_ + h;
  y_new_ = y_new;
  Step s;
  s.t0 = t_old_;
  s.t1 = t_new_;
  t_ = t_new_;
  y_ = y_new;
  // The events at the step's end, and with them the next step's f and J (the same point).
  Events g{};
  const int flag = system_.event_count() > 0
                       ? system_.linearize(t_, y_.data(), f0_.data(), jacobian_.data(), dfdt_.data(), g.data())
                       : 1;
  if (flag < 0) throw NumericalError("RODAS: unrecoverable failure of the right-hand side");
  linearized_ = flag == 0;
  if (!linearized_) g = events_at(t_new_, y_new_);
  double first = t_new_;
  s.fired = fired(g, first);
  if (!s.fired.empty()) {
    s.t1 = first;
    g = step_to_event(first, s.fired);
  }
  g_ = g;
  for (int i = 0; i < n_; ++i) {
    if (!std::isfinite(y_[i])) throw NumericalError(fmt::format("state became non-finite at scaled time {:.6g}", t_));
  }
  if (t_ >= settings_.max_time) {
    throw TimeBudgetExceeded(fmt::format("scaled time {:.6g} exceeds the budget {:.6g}", t_, settings_.max_time));
  }
  return s;
}

void RodasIntegrator::dense_output() {  // from the stages of the last attempt
  const auto& [g1, g2, g3, g4, g5] = stages_;
  for (int i = 0; i < n_; ++i) {
    cont3_[i] = C::d21 * g1[i] + C::d22 * g2[i] + C::d23 * g3[i] + C::d24 * g4[i] + C::d25 * g5[i];
    cont4_[i] = C::d31 * g1[i] + C::d32 * g2[i] + C::d33 * g3[i] + C::d34 * g4[i] + C::d35 * g5[i];
  }
}

RodasIntegrator::Vec RodasIntegrator::interpolate(double t) const {  // Hairer & Wanner IV (7.30)
  Vec y{};
  const double h = t_new_ - t_old_;
  const double s = h != 0.0 ? (t - t_old_) / h : 1.0, s1 = 1.0 - s;
  for (int i = 0; i < n_; ++i) y[i] = y_old_[i] * s1 + s * (y_new_[i] + s1 * (cont3_[i] + s * cont4_[i]));
  return y;
}

std::vector<double> RodasIntegrator::state() const { return std::vector<double>(y_.begin(), y_.begin() + n_); }

std::vector<double> RodasIntegrator::state_at(double t) const {
  const Vec y = interpolate(t);
  return std::vector<double>(y.begin(), y.begin() + n_);
}

}  // namespace bounce::dynamics::detail

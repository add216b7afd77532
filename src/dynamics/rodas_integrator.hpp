#pragma once
// Private: the RODAS engine of stiff.hpp, a Rosenbrock method of order 4 with an
// embedded order-3 error estimate and an order-3 dense output (Hairer & Wanner,
// Solving ODEs II, §IV.7, with the coefficients of Hairer's rodas.f), the step-size
// controller of Gustafsson (Hairer & Wanner IV.8, (8.21)) and event location on the
// dense output (event_locator.hpp, shared with the explicit engine).
//
// Written for the small systems of bounce (n <= 8, state on the stack): see
// stiff.hpp for why a library engine is not used here.

#include <array>
#include <vector>

#include "stiff.hpp"

namespace bounce::dynamics::detail {

class RodasIntegrator final : public StiffIntegrator {
 public:
  static constexpr int capacity = 8;
  static constexpr int max_events = 8;

  RodasIntegrator(const StiffSystem& system, const std::vector<double>& y0, double t0, const StiffSettings& settings);

  Step step() override;
  std::vector<double> state() const override;
  std::vector<double> state_at(double t) const override;
  long steps() const override { return steps_; }
  void disable_event(int index) override { enabled_.at(static_cast<std::size_t>(index)) = false; }

 private:
  using Vec = std::array<double, capacity>;
  using Mat = std::array<double, capacity * capacity>;
  /// One trial step of size h from (t_, y_): y_new and its error estimate; false
  /// when a stage left the system's domain.
  bool attempt(double h, Vec& y_new, Vec& error);
  /// f, J and f_t at (t_, y_), once per step (a rejected attempt reuses them); false outside
  /// the domain.
  bool linearize();
  /// Solves (I/(gamma h) - J) g = b in place.
  void solve(Vec& g, double gamma_h) const;
  double error_norm(const Vec& y_new, const Vec& error) const;
  double accepted_step(Vec& y_new);
  double initial_step();
  void dense_output();
  Vec interpolate(double t) const;
  using Events = std::array<double, max_events>;
  Events events_at(double t, const Vec& y) const;
  std::vector<int> fired(const Events& g, double& first) const;
  Events step_to_event(double first, const std::vector<int>& fired);

  const StiffSystem& system_;
  StiffSettings settings_;
  int n_;
  double t_;
  Vec y_{};
  double h_;
  // Dense output of the last accepted step: from (t_old_, y_old_) to (t_new_, y_new_).
  double t_old_, t_new_;
  Vec y_old_{}, y_new_{}, cont3_{}, cont4_{};
  // Stages of the last attempt (for the dense output).
  std::array<Vec, 5> stages_{};
  std::vector<bool> enabled_;
  Events g_{};  // event functions at (t_, y_)
  bool (*factorize_)(double*, int*) = nullptr;             // LU for the m_ coupled components
  void (*solve_)(const double*, const int*, double*) = nullptr;
  int m_ = 0;  // the coupled components 0..m_-1; m_..n_-1 are quadratures (StiffSystem::quadratures)
  // The linearization at (t_, y_), and the LU of the coupled block of the last attempt.
  bool linearized_ = false;
  Vec f0_{}, dfdt_{};
  Mat jacobian_{}, lu_{};
  std::array<int, capacity> pivot_{};
  long steps_ = 0;
  bool first_step_ = true, last_rejected_ = false;
  double h_old_ = 0.0, error_old_ = 0.0;
};

}  // namespace bounce::dynamics::detail

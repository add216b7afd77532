// The fundamental solutions of the asperity law's linear motion between breaks
// (dynamics/tangential.hpp), integrated together with the normal collision.
#include <algorithm>
#include <array>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "bounce/core/error.hpp"
#include "bounce/dynamics/tangential.hpp"
#include "normal_system.hpp"

namespace bounce::dynamics {

std::vector<FundamentalSample> fundamental_solutions(const models::NormalForceModel& model, double mass, double gn,
                                                     const models::TangentialModel& tangential,
                                                     const std::vector<double>& times, double tolerance) {
  namespace odeint = boost::numeric::odeint;
  using State = detail::State<7>;  // x, v, normal dissipation (the normal collision); y1, y1', y2, y2'
  const double xi0 = model.reference_overlap(gn);
  const double energy_unit = mass * gn * gn;
  const detail::NormalScaled normal{&model, xi0, gn, xi0 / energy_unit};
  // K = mu (xi0 / zeta0) f / kappa, BSHP96 (10) with (35); no shear in tension.
  const double k_scale = tangential.friction * (xi0 / tangential.asperity_size) / tangential.kappa;
  auto stiffness = [&](const State& y) {
    State unused{};
    return k_scale * std::max(normal(y, unused), 0.0);
  };
  auto system = [&](const State& y, State& dydt, double) {
    const double k = k_scale * std::max(normal(y, dydt), 0.0);
    dydt[3] = y[4];
    dydt[4] = -k * y[3];
    dydt[5] = y[6];
    dydt[6] = -k * y[5];
  };
  std::vector<FundamentalSample> out;
  State y{model.cutoff_overlap(gn) / xi0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0};
  auto stepper = odeint::make_dense_output(tolerance, tolerance, odeint::runge_kutta_dopri5<State>());
  odeint::integrate_times(stepper, system, y, times.begin(), times.end(), 1e-6, [&](const State& s, double) {
    out.push_back({s[3], s[4], s[5], s[6], stiffness(s)});
  });
  if (out.size() != times.size()) throw NumericalError("the fundamental solutions stopped early");
  return out;
}

}  // namespace bounce::dynamics

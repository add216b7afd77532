#pragma once
// The unit viscoelastic collision shared by the benchmarks: C0 = m = g = 1, so that
// kappa = (3/2)(5/4)^{3/5} A (BP04 (8.70)), timed through bounce's integration engine.
#include <cmath>

#include <benchmark/benchmark.h>

#include "bounce/analytic/master_curve.hpp"
#include "bounce/dynamics/normal_collision.hpp"
#include "bounce/models/normal_force.hpp"

namespace bench {

/// 1/((3/2)(5/4)^{3/5}): A of the unit problem per unit kappa, BP04 (8.70).
inline const double kappa_to_a = 1.0 / (1.5 * std::pow(1.25, 0.6));

/// Times integrate_normal_collision on the unit problem at this kappa; sets the counters
/// "error" (against the master curve of options.end_rule) and "steps".
inline void time_unit_collision(benchmark::State& state, double kappa,
                                const bounce::dynamics::NormalCollisionOptions& options) {
  const auto force = bounce::models::make_viscoelastic_force({1.0, 1.0, 1.0}, kappa * kappa_to_a);
  double e = 0.0;
  long steps = 0;
  for (auto _ : state) {
    const auto out = bounce::dynamics::integrate_normal_collision(*force, 1.0, 1.0, options);
    e = out.cor;
    steps = out.steps;
  }
  state.counters["error"] = std::abs(e - bounce::analytic::master_cor(kappa, options.end_rule));
  state.counters["steps"] = static_cast<double>(steps);
}

}  // namespace bench

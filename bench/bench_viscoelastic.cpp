// Cost per viscoelastic collision: the master curve and direct integration, at
// several kappa and both end rules. The error of each against the master curve
// (itself checked to 1e-12 against a long-double reference) is a counter.
// bench/viscoelastic_vs_scipy.py runs this beside a scipy reference.
#include <cmath>

#include <benchmark/benchmark.h>

#include "bounce/analytic/master_curve.hpp"
#include "bounce/dynamics/normal_collision.hpp"
#include "bounce/models/normal_force.hpp"

namespace {
using bounce::dynamics::EndRule;

// A unit problem: C0 = m = 1, so kappa = (3/2)(5/4)^{3/5} A at g = 1.
const double kappa_to_a = 1.0 / (1.5 * std::pow(1.25, 0.6));  // 1/((3/2)(5/4)^{3/5}), BP04 (8.70)

void master(benchmark::State& state, EndRule rule) {
  // Cycle through 64 kappa spread over [1e-3, 1e3] so that nothing is cached.
  double kappas[64];
  for (int i = 0; i < 64; ++i) kappas[i] = std::pow(10.0, -3.0 + 6.0 * i / 63.0);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bounce::analytic::master_cor(kappas[i++ & 63], rule));
  }
}

void integrate(benchmark::State& state, EndRule rule) {
  const double kappa = static_cast<double>(state.range(0)) / 100.0;
  const bounce::models::HertzGeometry g{1.0, 1.0, 1.0};
  const auto force = bounce::models::make_viscoelastic_force(g, kappa * kappa_to_a);
  bounce::dynamics::NormalCollisionOptions options;
  options.end_rule = rule;
  double e = 0.0;
  long steps = 0;
  for (auto _ : state) {
    const auto out = bounce::dynamics::integrate_normal_collision(*force, 1.0, 1.0, options);
    e = out.cor;
    steps = out.steps;
  }
  state.counters["kappa"] = kappa;
  state.counters["error"] = std::abs(e - bounce::analytic::master_cor(kappa, rule));
  state.counters["steps"] = static_cast<double>(steps);
}
}  // namespace

BENCHMARK_CAPTURE(master, overlap, EndRule::overlap);
BENCHMARK_CAPTURE(master, force, EndRule::force);
BENCHMARK_CAPTURE(integrate, overlap, EndRule::overlap)->Arg(1)->Arg(30)->Arg(300)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(integrate, force, EndRule::force)->Arg(1)->Arg(30)->Arg(300)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();

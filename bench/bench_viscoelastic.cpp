// Cost per viscoelastic collision: the master curve and direct integration, at
// several kappa and both end rules. The error of each against the master curve
// (itself checked to 1e-12 against a long-double reference) is a counter.
// bench/viscoelastic_vs_scipy.py runs this beside a scipy reference.
#include <cmath>

#include <benchmark/benchmark.h>

#include "bounce/analytic/master_curve.hpp"
#include "unit_collision.hpp"

namespace {
using bounce::models::EndRule;

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
  bounce::dynamics::NormalCollisionOptions options;
  options.end_rule = rule;
  bench::time_unit_collision(state, kappa, options);
  state.counters["kappa"] = kappa;
}
}  // namespace

BENCHMARK_CAPTURE(master, overlap, EndRule::overlap);
BENCHMARK_CAPTURE(master, force, EndRule::force);
BENCHMARK_CAPTURE(integrate, overlap, EndRule::overlap)->Arg(1)->Arg(30)->Arg(300)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(integrate, force, EndRule::force)->Arg(1)->Arg(30)->Arg(300)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();

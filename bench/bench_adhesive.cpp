// K13's model (krijt): the cost of a collision and of K13 fig. 4's COR curve (water ice,
// the radius of K13 §3), across T_vis, with our RODAS engine and with SUNDIALS CVODE
// side by side (docs/benchmarks.md). The error of each collision against a CVODE run
// at tolerance 1e-12 is a counter. bench/adhesive_vs_scipy.py runs this beside a scipy
// implementation of the same equations.
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include "bounce/analysis/collide.hpp"
#include "bounce/analysis/curve.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/materials_table.hpp"

namespace {

constexpr double k13_sphere_radius = 2.0353e-6;  // t_H(K13 (22)) = 1.4e-8 s at 8 m/s

const bounce::Pair& ice() {
  static const bounce::Pair p =
      bounce::Pair::identical(bounce::MaterialTable::builtin().at("water-ice"), k13_sphere_radius);
  return p;
}

bounce::models::Model krijt(double tvis) { return bounce::models::make_model(ice(), "krijt", {{"tvis", tvis}}); }

bounce::analysis::CollideOptions engine(int which, double tolerance) {
  bounce::analysis::CollideOptions o;
  o.stiff_engine = which == 0 ? bounce::dynamics::StiffEngine::rodas : bounce::dynamics::StiffEngine::cvode;
  o.adhesive_tolerance = tolerance;
  return o;
}

// Arguments: velocity x 10, -log10 T_vis, engine (0 RODAS, 1 CVODE), -log10 tolerance.
void collision(benchmark::State& state) {
  const double velocity = static_cast<double>(state.range(0)) / 10.0;
  const double tvis = std::pow(10.0, -static_cast<double>(state.range(1)));
  const auto options = engine(static_cast<int>(state.range(2)), std::pow(10.0, -static_cast<double>(state.range(3))));
  const auto model = krijt(tvis);
  bounce::dynamics::CollisionOutcome out;
  for (auto _ : state) out = bounce::analysis::collide(ice(), model, velocity, options);
  const auto reference = bounce::analysis::collide(ice(), model, velocity, engine(1, 1e-12));
  state.counters["velocity"] = velocity;
  state.counters["tvis"] = tvis;
  state.counters["engine"] = static_cast<double>(state.range(2));
  state.counters["tolerance"] = options.adhesive_tolerance;
  state.counters["cor"] = out.cor;
  state.counters["error"] = std::abs(out.cor - reference.cor);
  state.counters["closure"] = std::abs(out.energy.closure_error / out.energy.initial_kinetic);
  state.counters["steps"] = static_cast<double>(out.steps);
  state.counters["stick"] = out.outcome == bounce::dynamics::Outcome::stick;
}

std::vector<double> fig4_velocities() {  // 100 velocities, 0.1 to 100 m/s (geometric)
  std::vector<double> v(100);
  for (int i = 0; i < 100; ++i) v[i] = 0.1 * std::pow(1000.0, i / 99.0);
  return v;
}

// The K13 fig. 4 curve at T_vis = 10^-range(0) s: its time / 100 is the mean cost of a
// collision at that T_vis (sticking and bouncing ones alike).
void fig4_curve(benchmark::State& state) {
  const double tvis = std::pow(10.0, -static_cast<double>(state.range(0)));
  const auto v = fig4_velocities();
  const auto model = krijt(tvis);
  for (auto _ : state) benchmark::DoNotOptimize(bounce::analysis::collide_curve(ice(), model, v));
  state.counters["tvis"] = tvis;
}

}  // namespace

BENCHMARK(collision)->ArgsProduct({{20, 80, 300}, {11}, {0, 1}, {8, 9, 10}})->Unit(benchmark::kMillisecond);
BENCHMARK(collision)->ArgsProduct({{80}, {8, 9, 10, 11, 12, 13, 14, 15, 16}, {0, 1}, {8, 9}})->Unit(benchmark::kMillisecond);
BENCHMARK(fig4_curve)->DenseRange(8, 16)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_MAIN();

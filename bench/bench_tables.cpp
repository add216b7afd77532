// Cost of eps^T from a table (bounce table --tangential-velocities) against the direct
// integration it replaces, side by side at the same (g^N, g^T): BSHP96 fig. 2 (b)'s grains
// (zeta0 = 2e-4 R_eff) at g^N = 1 m/s, with no break (g^T = 0.01), a few (0.1) and many (1).
#include <cmath>

#include <benchmark/benchmark.h>

#include "bounce/analysis/tables.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/materials_table.hpp"

namespace {
const bounce::Pair& pair() {
  static const bounce::Pair p = bounce::Pair::identical(bounce::MaterialTable::builtin().at("ice-bshp96"), 0.01);
  return p;
}
const bounce::models::Model& model() {
  static const bounce::models::Model m = bounce::models::make_model(
      pair(), "viscoelastic",
      {{"A", 1e-6}, {"asperity", 2e-4 * pair().effective_radius()}, {"friction", std::sqrt(2e-4)},
       {"asperity_form", "published"}});  // the form a table holds
  return m;
}
const bounce::analysis::TangentialTable& table() {
  static const bounce::analysis::TangentialTable t =
      bounce::analysis::build_tangential_table(pair(), model(), 0.01, 10.0, 1e-3, 1.0);
  return t;
}

void tangential_table(benchmark::State& state, double gt) {
  double gn = 1.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(table().cor(gn, gt));
    gn = gn < 1.01 ? gn * 1.0001 : 1.0;  // vary the input so nothing is cached
  }
  state.counters["breaks"] = static_cast<double>(table().breaks(1.0, gt));
}

void tangential_direct(benchmark::State& state, double gt) {
  bounce::analysis::CollideOptions o;
  o.tangential_velocity = gt;
  double gn = 1.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bounce::analysis::collide(pair(), model(), gn, o).tangential->cor);
    gn = gn < 1.01 ? gn * 1.0001 : 1.0;
  }
}
}  // namespace

BENCHMARK_CAPTURE(tangential_table, no_break, 0.01)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tangential_direct, no_break, 0.01)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tangential_table, few_breaks, 0.1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tangential_direct, few_breaks, 0.1)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tangential_table, many_breaks, 1.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(tangential_direct, many_breaks, 1.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();

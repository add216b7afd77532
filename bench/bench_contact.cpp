// Cost of the static contact laws for one state at given force: the closed forms
// (Hertz, JKR, DMT) against Maugis-Dugdale, which solves (MD1) by root finding.
// The ratio tells how much the transition theory costs over JKR.
#include <benchmark/benchmark.h>

#include "bounce/contact/law.hpp"
#include "bounce/pair/materials_table.hpp"

namespace {
const bounce::Pair& pair() {
  static const bounce::Pair p =
      bounce::Pair::identical(bounce::MaterialTable::builtin().at("water-ice"), 1e-6);
  return p;
}

void contact_at_force(benchmark::State& state, const char* law) {
  const auto model = bounce::contact::make_contact_law(law, pair());
  double force = 1e-7;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model->at_force(force));
    force = force < 1e-6 ? force * 1.01 : 1e-7;  // vary the input so nothing is cached
  }
}
}  // namespace

BENCHMARK_CAPTURE(contact_at_force, hertz, "hertz");
BENCHMARK_CAPTURE(contact_at_force, jkr, "jkr");
BENCHMARK_CAPTURE(contact_at_force, dmt, "dmt");
BENCHMARK_CAPTURE(contact_at_force, maugis, "maugis");
BENCHMARK_MAIN();

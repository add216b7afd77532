// Cost of a collision atlas lookup (docs/atlas.md) against the collision it replaces, side by
// side at the same pairs: K13's ice (krijt, T_vis = 1e-11 s) with radii of 1-10 um, random
// (R1, R2, v) drawn once, looked up in turn (C API, checked C++ and the collision itself).
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "bounce/analysis/atlas.hpp"
#include "bounce/api/atlas.hpp"
#include "bounce/atlas.h"
#include "bounce/models/registry.hpp"

namespace {

const bounce::analysis::AtlasRequest& request() {
  static const auto r = bounce::api::atlas_request({{"model", "krijt"}, {"tvis", "1e-11"}, {"materials", "water-ice"},
                                                    {"radius", "1e-6:1e-5:4"}, {"velocity", "0.3:20:5"}, {"tol", "1e-3"}});
  return r;
}

const bounce::analysis::Atlas& atlas() {
  static const bounce::analysis::Atlas a = bounce::analysis::build_atlas(request());
  return a;
}

struct Query {
  double r1, r2, v;
};
const std::vector<Query>& queries() {
  static const std::vector<Query> q = [] {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Query> out;
    while (out.size() < 4096) {
      const double r1 = 2e-6 * std::pow(5.0, u(rng)), r2 = 2e-6 * std::pow(5.0, u(rng));
      out.push_back({r1, r2, 0.3 * std::pow(20.0 / 0.3, u(rng))});
    }
    return out;
  }();
  return q;
}

void atlas_c_lookup(benchmark::State& state) {
  const std::string path = "/tmp/bounce-bench-atlas.h5";
  bounce::analysis::write_atlas(atlas(), path);
  bounce_atlas* c = bounce_atlas_open(path.c_str(), "krijt", nullptr, 0);
  std::size_t i = 0;
  for (auto _ : state) {
    const Query& q = queries()[i++ & 4095];
    benchmark::DoNotOptimize(bounce_atlas_cor(c, q.r1, q.r2, q.v));
  }
  bounce_atlas_close(c);
}
BENCHMARK(atlas_c_lookup);

void atlas_checked_lookup(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    const Query& q = queries()[i++ & 4095];
    benchmark::DoNotOptimize(atlas().cor(q.r1, q.r2, q.v));
  }
}
BENCHMARK(atlas_checked_lookup);

// n random points in one call (the C API's bounce_atlas_cor_n, Python's vectorised cor). The
// 4096 are looked up again and again, and the branch predictor learns their outcomes (stick or
// bounce, which cell): 2e6 points are as new to it as a coagulation code's are.
void atlas_many(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> r1(n), r2(n), v(n), out(n);
  for (std::size_t i = 0; i < n; ++i) {
    r1[i] = 2e-6 * std::pow(5.0, u(rng));
    r2[i] = 2e-6 * std::pow(5.0, u(rng));
    v[i] = 0.3 * std::pow(20.0 / 0.3, u(rng));
  }
  atlas();  // built before the clock starts
  for (auto _ : state) {
    atlas().cor_many(n, r1.data(), r2.data(), v.data(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["ns_per_lookup"] = benchmark::Counter(static_cast<double>(state.iterations() * n),
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(atlas_many)->Arg(4096)->Arg(2000000);

void atlas_v_stick(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    const Query& q = queries()[i++ & 4095];
    benchmark::DoNotOptimize(atlas().v_stick_unchecked(q.r1, q.r2));
  }
}
BENCHMARK(atlas_v_stick);

// The collision the lookup replaces (RODAS, tolerance 1e-8).
void collide_direct(benchmark::State& state) {
  std::size_t i = 0;
  const auto& a = atlas();
  for (auto _ : state) {
    const Query& q = queries()[i++ & 4095];
    const bounce::Pair pair(bounce::sphere(a.material1, q.r1), bounce::sphere(a.material2, q.r2));
    const auto model = bounce::models::make_model(pair, "krijt", request().model_parameters);
    benchmark::DoNotOptimize(bounce::analysis::collide(pair, model, q.v, request().options).cor);
  }
}
BENCHMARK(collide_direct)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

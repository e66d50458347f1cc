// Cost of the truth: per 100 Hz sample over seed 004's 1800 s tractor field run (boustrophedon,
// rough ground, 50 Hz pure-pursuit guidance), and per sample of an open-loop line.
#include <ctime>

#include <benchmark/benchmark.h>

#include "truth_test_scenarios.h"

namespace hil::truth {
namespace {

void RunScenario(benchmark::State& state, const TruthConfig& c, double duration_s) {
  const std::int64_t n = static_cast<std::int64_t>(duration_s * 100);
  long steps = 0, reinits = 0, roots = 0;
  double seconds = 0;
  for (auto _ : state) {
    const std::clock_t t0 = std::clock();  // process CPU time: the machine is shared
    TruthIntegrator truth(c);
    for (std::int64_t k = 0; k <= n; ++k)
      benchmark::DoNotOptimize(truth.Sample(TimeFromNs(k * 10'000'000LL)));
    steps = truth.steps();
    reinits = truth.reinits();
    roots = truth.root_events();
    seconds += static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
  }
  state.SetItemsProcessed(state.iterations() * (n + 1));
  state.counters["cpu_us_per_sample"] =
      seconds * 1e6 / static_cast<double>(state.iterations() * (n + 1));
  state.counters["cvode_steps"] = static_cast<double>(steps);
  state.counters["reinits"] = static_cast<double>(reinits);
  state.counters["vertex_events"] = static_cast<double>(roots);
}

void BM_TractorField1800sAt100Hz(benchmark::State& state) {
  RunScenario(state, testing::TractorFieldConfig(), 1800);
}
BENCHMARK(BM_TractorField1800sAt100Hz)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_OpenLoopLine1800sAt100Hz(benchmark::State& state) {
  TruthConfig c;
  c.origin = {35.4796096, 50.5979765, 1312};
  c.speed_mps = 1;
  RunScenario(state, c, 1800);
}
BENCHMARK(BM_OpenLoopLine1800sAt100Hz)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_RoughRectangleWithVibration120sAt100Hz(benchmark::State& state) {
  RunScenario(state, testing::RoughTurningConfig(), 120);
}
BENCHMARK(BM_RoughRectangleWithVibration120sAt100Hz)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace hil::truth

BENCHMARK_MAIN();

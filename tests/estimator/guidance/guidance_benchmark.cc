// Per-tick cost of the path trackers on a boustrophedon (a 40-row field, ~40 000 vertices), the
// vehicle moving 0.1 m per tick so the projection hint is exercised as in a run.
#include <cmath>
#include <numbers>

#include <benchmark/benchmark.h>

#include "hil/estimator/guidance/path_file.h"
#include "hil/estimator/guidance/path_tracker.h"

namespace hil::estimator::guidance {
namespace {

const PlannedPath& Field() {
  static const PlannedPath p = ParsePathText(
      "hil-path 1\nboustrophedon start_m=0,0 heading_deg=0 row_length_m=200 row_spacing_m=6 "
      "rows=40 turn_radius_m=3 step_m=0.05\n",
      "bench");
  return p;
}

template <typename Controller, typename Config>
void Run(benchmark::State& state) {
  const PlannedPath& path = Field();
  Controller ctl{Config{}};
  double s = 0;
  std::size_t hint = 0;
  for (auto _ : state) {
    s = std::fmod(s + 0.1, path.length_m() - 1.0);
    VehiclePose2d pose;
    pose.p_EN_m = path.PointAt(s, hint, &hint) + Eigen::Vector2d(0.05, 0.02);
    pose.yaw_rad = std::numbers::pi / 2;
    pose.speed_mps = 1.0;
    TrackingCommand c = ctl.Update(path, pose);
    benchmark::DoNotOptimize(c);
  }
}

void BM_PurePursuitTick(benchmark::State& state) { Run<PurePursuit, PurePursuitConfig>(state); }
void BM_StanleyTick(benchmark::State& state) { Run<Stanley, StanleyConfig>(state); }
BENCHMARK(BM_PurePursuitTick);
BENCHMARK(BM_StanleyTick);

}  // namespace
}  // namespace hil::estimator::guidance

BENCHMARK_MAIN();

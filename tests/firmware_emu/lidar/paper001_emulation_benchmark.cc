// Paper 001's range devices against the targets: the RPLIDAR at 10 Hz × 360 points
// (express scan, 3597 samples/s) ≥ 100× real time, and the four TF-Luna rangefinders at 100 Hz
// ≥ 1000× real time, in the small test greenhouse with the vehicle weaving along aisle 0. One
// emulated second per iteration: the real-time factor is 1 s divided by the time per iteration.
#include <vector>

#include <benchmark/benchmark.h>

#include "hil/firmware_emu/lidar/rplidar_device.h"
#include "hil/firmware_emu/lidar/rplidar_request.h"
#include "hil/firmware_emu/rangefinder/tf_luna_device.h"

#include "aisle_truth.h"

namespace hil {
namespace {

void BM_RplidarTenHertzBy360PointsOneSecond(benchmark::State& state) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  lidar::RplidarConfig c;
  c.rotation_hz = 10;
  c.express_sample_us = 278;
  lidar::RplidarDevice dev(c, w, 1);
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(0.0), lidar::EncodeRequest(0x82, std::string(5, '\0')), out);
  const test::AisleTruth truth;
  Time end{};
  std::size_t bytes = 0;
  for (auto _ : state) {
    end += std::chrono::seconds(1);
    while (dev.next_event_time() <= end) {
      out.clear();
      dev.OnEvent(truth.At(dev.next_event_time()), out);
      for (const SerialMessage& m : out.serial) bytes += m.bytes.size();
    }
  }
  state.counters["realtime_factor"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["bytes_per_s"] =
      static_cast<double>(bytes) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_RplidarTenHertzBy360PointsOneSecond);

void BM_FourRangefindersOneSecond(benchmark::State& state) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  std::vector<rangefinder::TfLunaDevice> units;
  // right-front, right-rear, left-front, left-rear, looking sideways (yaw from forward)
  const double mounts[4][2] = {{0.3, -90}, {-0.3, -90}, {0.3, 90}, {-0.3, 90}};
  for (int i = 0; i < 4; ++i) {
    rangefinder::TfLunaConfig c;
    c.mount = {mounts[i][0], 0, 0.15, mounts[i][1]};
    units.emplace_back(c, w, static_cast<std::uint64_t>(i + 1));
  }
  const test::AisleTruth truth;
  DeviceOutput out;
  Time end{};
  std::size_t frames = 0;
  for (auto _ : state) {
    end += std::chrono::seconds(1);
    for (auto& u : units) {
      while (u.next_event_time() <= end) {
        out.clear();
        u.OnEvent(truth.At(u.next_event_time()), out);
        frames += out.serial.size();
      }
    }
  }
  state.counters["realtime_factor"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["frames_per_s"] =
      static_cast<double>(frames) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_FourRangefindersOneSecond);

}  // namespace
}  // namespace hil

BENCHMARK_MAIN();

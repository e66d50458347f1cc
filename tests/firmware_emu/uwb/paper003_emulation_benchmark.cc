// Paper 003's devices against the target (UWB and WT901C emulation ≥ 1000× real time):
// one emulated second of the UWB tag at 5 Hz (both outputs, an NLOS zone on the path) and of the
// WT901C at 10 Hz (four packets per cycle) per iteration; the real-time factor is 1 s divided by
// the time per iteration.
#include <benchmark/benchmark.h>

#include "hil/firmware_emu/attitude/wt901c_device.h"
#include "hil/firmware_emu/uwb/uwb_tag_device.h"

namespace hil {
namespace {

TruthSample Truth(Time t) {
  TruthSample s;
  s.t = t;
  s.p_NB_N_m = {-7.0 + 0.5 * ToSeconds(t), -7.0, 0.0};
  s.f_B_mps2 = {0, 0, kStandardGravity_mps2};
  return s;
}

void BM_UwbAndWt901cOneSecond(benchmark::State& state) {
  uwb::UwbTagConfig uc;
  uc.output = uwb::UwbOutput::kBoth;
  uc.errors.nlos_zones.push_back({Eigen::Vector2d(-5, -7), 3.0, 0.2, 1.0, 0.3, 0.1});
  uwb::UwbTagDevice tag(uc, 1);
  wit::Wt901cDevice wit(wit::Wt901cConfig{}, 1);
  DeviceOutput out;
  Time end{};
  std::size_t bytes = 0;
  for (auto _ : state) {
    end += std::chrono::seconds(1);
    for (Device* d : {static_cast<Device*>(&tag), static_cast<Device*>(&wit)}) {
      while (d->next_event_time() <= end) {
        out.clear();
        d->OnEvent(Truth(d->next_event_time()), out);
        for (const SerialMessage& m : out.serial) bytes += m.bytes.size();
      }
    }
  }
  state.counters["realtime_factor"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  benchmark::DoNotOptimize(bytes);
}
BENCHMARK(BM_UwbAndWt901cOneSecond);

}  // namespace
}  // namespace hil

BENCHMARK_MAIN();

// TruthAhead (truth_ahead.h): the truth sampled ahead on a thread from the devices' predicted
// schedule gives, bit for bit, the samples of one integrator asked the same times in order, both
// where the schedule holds and where it changes (a device's rate changed by a host: the times
// the worker did not predict come from the caller's own integrator).
#include "hil/harness/engine/truth_ahead.h"

#include <chrono>
#include <optional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../run/expect_same_sample.h"
#include "../truth/truth_test_scenarios.h"

namespace hil::harness {
namespace {

using testing::ExpectSameSample;

Time Ms(long long ms) { return TimeFromNs(ms * 1'000'000LL); }

// Two devices as a scheduler sees them: an IMU at 100 Hz and a receiver whose period is
// `gnss_period_ms(t)`; each event asks for the truth after Plan(), as Scheduler::AheadSample does.
// With `fill_first`, the caller starts once the worker holds kAheadEvents samples (2.55 s ahead).
template <typename GnssPeriod>
TruthAhead::Counts RunAndCompare(long long t_end_ms, GnssPeriod gnss_period_ms, bool fill_first) {
  const truth::TruthConfig config = truth::testing::RoughTurningConfig();
  TruthAhead ahead(config);
  truth::TruthIntegrator reference(config);
  long long imu = 0, gnss = 0;
  std::optional<long long> last_imu, last_gnss;
  std::size_t asked = 0;
  while (std::min(imu, gnss) <= t_end_ms) {
    std::vector<TruthAhead::DeviceSchedule> plan(2);
    plan[0] = {Ms(imu), last_imu ? Ms(imu - *last_imu) - Time{} : Duration{}};
    plan[1] = {Ms(gnss), last_gnss ? Ms(gnss - *last_gnss) - Time{} : Duration{}};
    ahead.Plan(plan);
    if (fill_first && asked == 1) {
      for (int i = 0; i < 10000 && ahead.ready() < TruthAhead::kAheadEvents; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      EXPECT_EQ(ahead.ready(), TruthAhead::kAheadEvents);
    }
    const long long t = std::min(imu, gnss);
    ExpectSameSample(ahead.Sample(Ms(t)), reference.Sample(Ms(t)));
    ++asked;
    if (imu == t) {
      last_imu = imu;
      imu += 10;
    }
    if (gnss == t) {
      last_gnss = gnss;
      gnss += gnss_period_ms(t);
    }
  }
  const TruthAhead::Counts c = ahead.counts();
  EXPECT_EQ(c.hits + c.taken + c.misses, asked) << "every time answered once";
  return c;
}

TEST(TruthAheadTest, APeriodicScheduleIsSampledAheadBitForBit) {
  const TruthAhead::Counts c = RunAndCompare(
      60'000, [](long long) { return 200; }, false);
  EXPECT_EQ(c.misses, 0u) << "every time of a periodic schedule is predicted";
}

TEST(TruthAheadTest, TimesTheWorkerPassedComeFromTheCallersIntegratorBitForBit) {
  // the receiver at 5 Hz, then from t = 1 s every 201 ms (a host changed its rate): the worker,
  // 2.55 s ahead by then, passed those times on the old schedule
  const TruthAhead::Counts c = RunAndCompare(
      20'000, [](long long t) { return t < 1000 ? 200 : 201; }, true);
  EXPECT_GT(c.misses, 0u);
  EXPECT_GT(c.hits, 0u);
}

}  // namespace
}  // namespace hil::harness

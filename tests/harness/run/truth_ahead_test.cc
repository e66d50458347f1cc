// TruthAhead (truth_ahead.h): the truth sampled ahead on a thread from the devices' predicted
// schedule gives, bit for bit, the samples of one integrator asked the same times in order, both
// where the schedule holds and where it changes (a device's rate changed by a host: the times
// the worker did not predict come from the caller's own integrator).
#include "hil/harness/run/truth_ahead.h"

#include <chrono>
#include <vector>

#include <gtest/gtest.h>

#include "../truth/truth_test_scenarios.h"
#include "expect_same_sample.h"

namespace hil::harness {
namespace {

using testing::ExpectSameSample;

Time Ms(long long ms) { return TimeFromNs(ms * 1'000'000LL); }

// Two devices as a scheduler sees them: an IMU at 100 Hz and a receiver whose period is
// `gnss_period_ms(t)`; each event asks for the truth after Plan(), as Scheduler::AheadSample does.
template <typename GnssPeriod>
void RunAndCompare(long long t_end_ms, GnssPeriod gnss_period_ms, std::size_t* misses) {
  const truth::TruthConfig config = truth::testing::RoughTurningConfig();
  TruthAhead ahead(config);
  truth::TruthIntegrator reference(config);
  long long imu = 0, gnss = 0;
  std::optional<long long> last_imu, last_gnss;
  while (std::min(imu, gnss) <= t_end_ms) {
    std::vector<TruthAhead::DeviceSchedule> plan(2);
    plan[0] = {Ms(imu), last_imu ? Ms(imu - *last_imu) - Time{} : Duration{}};
    plan[1] = {Ms(gnss), last_gnss ? Ms(gnss - *last_gnss) - Time{} : Duration{}};
    ahead.Plan(plan);
    const long long t = std::min(imu, gnss);
    ExpectSameSample(ahead.Sample(Ms(t)), reference.Sample(Ms(t)));
    if (imu == t) {
      last_imu = imu;
      imu += 10;
    }
    if (gnss == t) {
      last_gnss = gnss;
      gnss += gnss_period_ms(t);
    }
  }
  *misses = ahead.misses();
  EXPECT_GT(ahead.ahead_hits(), 0u);
}

TEST(TruthAheadTest, APeriodicScheduleIsSampledAheadBitForBit) {
  std::size_t misses = 0;
  RunAndCompare(
      60'000, [](long long) { return 200; }, &misses);
  EXPECT_EQ(misses, 0u) << "every time of a periodic schedule is predicted";
}

TEST(TruthAheadTest, RateChangesAreMissedAndComputedBitForBit) {
  // the receiver's period changes every 7 s (5 Hz, then 3 Hz with an offset, then 4 Hz ...)
  std::size_t misses = 0;
  RunAndCompare(
      60'000, [](long long t) { return t / 7000 % 2 ? 333 : 250; }, &misses);
  EXPECT_GT(misses, 0u) << "the first times after a change are not predicted";
}

}  // namespace
}  // namespace hil::harness

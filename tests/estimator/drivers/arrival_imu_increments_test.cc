// The arrival-clock → increments path shared by the Razor text and J1939 IMU inputs.
#include "hil/estimator/drivers/arrival_imu_increments.h"

#include <gtest/gtest.h>

namespace hil::estimator::drivers {
namespace {

constexpr std::int64_t kMs = 1'000'000;
constexpr GpsTime kT0 = GpsTimeFromNs(1'000 * kNsPerSecond);

TEST(ArrivalImuIncrementsTest, StampsIntegratesAndCountsWhatItDrops) {
  ArrivalClock clock;
  ArrivalImuIncrements imu(0.5);
  ArrivalImuCounts counts;
  const Eigen::Vector3d w(0, 0, 0.2), f(0, 0, 9.8);
  // GIVEN no map from the host clock yet: the sample has no time
  EXPECT_FALSE(imu.Add(clock, 0, w, f, counts));
  EXPECT_EQ(counts.imu_no_time, 1u);
  // WHEN two references give the map (host 5 s ahead of GPS, same rate)
  clock.AddReference(5'000 * kMs, kT0);
  clock.AddReference(6'000 * kMs, kT0 + Nanoseconds{1'000 * kMs});
  // THEN samples every 10 ms become increments on GPS time (the first one only starts them)
  std::vector<ImuSample> out;
  for (int k = 0; k <= 10; ++k) {
    if (auto s = imu.Add(clock, 6'000 * kMs + k * 10 * kMs, w, f, counts)) out.push_back(*s);
  }
  ASSERT_EQ(out.size(), 10u);
  EXPECT_EQ(counts.imu_out, 10u);
  EXPECT_EQ(out.back().t, kT0 + Nanoseconds{1'100 * kMs});
  EXPECT_DOUBLE_EQ(out.back().dt_s, 0.01);
  EXPECT_NEAR(out.back().delta_angle_B_rad.z(), 0.2 * 0.01, 1e-15);
  EXPECT_NEAR(out.back().delta_velocity_B_mps.z(), 9.8 * 0.01, 1e-15);
  // AND a gap longer than 0.5 s is counted and restarts the integration
  EXPECT_FALSE(imu.Add(clock, 7'000 * kMs, w, f, counts));
  EXPECT_EQ(counts.imu_gap, 1u);
  EXPECT_TRUE(imu.Add(clock, 7'010 * kMs, w, f, counts));
  // AND after a reset the next sample only starts the sequence again
  imu.Reset();
  EXPECT_FALSE(imu.Add(clock, 7'020 * kMs, w, f, counts));
  EXPECT_EQ(counts.imu_no_time, 1u);
}

}  // namespace
}  // namespace hil::estimator::drivers

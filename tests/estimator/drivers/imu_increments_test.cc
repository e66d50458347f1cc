#include "hil/estimator/drivers/imu_increments.h"

#include <gtest/gtest.h>

namespace hil::estimator::drivers {
namespace {

/// GPS time `ms` milliseconds after the epoch.
constexpr GpsTime At(std::int64_t ms) { return GpsTimeFromNs(ms * 1'000'000); }

TEST(ImuIncrementsTest, TrapezoidOverEachIntervalAndRestartAfterAGap) {
  ImuIncrements inc(0.5);
  const Eigen::Vector3d w0(0.1, 0, 0), w1(0.3, 0, 0), f0(0, 0, 9.8), f1(0, 1.0, 9.8);
  EXPECT_FALSE(inc.Add(At(1000), w0, f0)) << "the first sample only starts the sequence";
  const auto s = inc.Add(At(1100), w1, f1);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->t, At(1100));
  EXPECT_DOUBLE_EQ(s->dt_s, 0.1);
  EXPECT_NEAR(s->delta_angle_B_rad.x(), 0.5 * (0.1 + 0.3) * 0.1, 1e-15);
  EXPECT_NEAR(s->delta_velocity_B_mps.y(), 0.5 * 1.0 * 0.1, 1e-15);
  // the sensor's own clock says the interval was a little longer (crystal offset)
  const auto own = inc.Add(At(1200), w1, f1, 0.10004);
  ASSERT_TRUE(own);
  EXPECT_DOUBLE_EQ(own->dt_s, 0.10004);
  EXPECT_FALSE(inc.Add(At(1800), w1, f1)) << "0.6 s is a gap";
  EXPECT_EQ(inc.gaps(), 1u);
  EXPECT_TRUE(inc.Add(At(1900), w1, f1)) << "the gap restarted the sequence";
  EXPECT_FALSE(inc.Add(At(1900), w1, f1)) << "a repeated time is no interval";
  inc.Restart();
  EXPECT_FALSE(inc.Add(At(2000), w1, f1));
  EXPECT_EQ(inc.increments(), 3u);
}

}  // namespace
}  // namespace hil::estimator::drivers

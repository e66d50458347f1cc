// navd.conf [odometry]: the keys of the gyro + wheel-odometry mode, and errors naming the line.
#include "hil/estimator/navd/navd_odometry_config.h"

#include <gtest/gtest.h>

#include "navd_conf_text.h"

namespace hil::estimator {
namespace {

using test::Error;
using test::Load;

TEST(NavdOdometryConfig, ReadsEveryKey) {
  const NavdConfig c = Load(
      "[input]\nimu_device = /dev/ttyIMU\n[odometry]\ndevice = /run/odo.fifo\nwheel_radius_m = "
      "0.12\ntrack_m = 0.6\ncounts_per_rev = 2048\norigin_lat_deg = 35.5\norigin_lon_deg = "
      "50.6\norigin_height_m = 1300\ninitial_e_m = -1.05\ninitial_n_m = -1.5\n"
      "initial_heading_deg = 90\nalign_s = 3\ngyro_arw = 2e-4\ngyro_bias_rw = 3e-5\n"
      "init_gyro_bias_std = 0.002\nodo_yaw_std_rad = 0.01\nodo_distance_std_fraction = 0.02\n"
      "odo_lateral_std_fraction = 0.003\nwait_s = 1.5\n");
  const NavdOdometryConfig& o = c.odometry;
  EXPECT_TRUE(o.enabled());
  EXPECT_EQ(o.device, "/run/odo.fifo");
  EXPECT_DOUBLE_EQ(o.wheel_radius_m, 0.12);
  EXPECT_DOUBLE_EQ(o.track_m, 0.6);
  EXPECT_EQ(o.counts_per_rev, 2048);
  EXPECT_DOUBLE_EQ(o.origin_height_m, 1300);
  EXPECT_DOUBLE_EQ(o.initial_e_m, -1.05);
  EXPECT_DOUBLE_EQ(o.initial_heading_deg, 90);
  EXPECT_DOUBLE_EQ(o.align_s, 3);
  EXPECT_DOUBLE_EQ(o.gyro_bias_rw, 3e-5);
  EXPECT_DOUBLE_EQ(o.odo_lateral_std_fraction, 0.003);
  EXPECT_DOUBLE_EQ(o.wait_s, 1.5);
  EXPECT_FALSE(Load("[input]\nimu_device = /dev/ttyIMU\n").odometry.enabled());
}

TEST(NavdOdometryConfig, ErrorsNameTheLineAndKey) {
  EXPECT_EQ(Error("[odometry]\ndevice = x\ntrack_m = 0\n"),
            "n.conf:3: [odometry] track_m: value 0 out of range [0.05, 10]");
  EXPECT_EQ(Error("[odometry]\ncounts_per_rev = 12.5\n"),
            "n.conf:2: [odometry] counts_per_rev: expected a whole number of counts, got '12.5'");
  EXPECT_EQ(Error("[odometry]\nwheel_radius_m = abc\n"),
            "n.conf:2: [odometry] wheel_radius_m: expected a number, got 'abc'");
  EXPECT_EQ(Error("[odometry]\nslip = 0.1\n"), "n.conf:2: [odometry] slip: unknown key");
}

}  // namespace
}  // namespace hil::estimator

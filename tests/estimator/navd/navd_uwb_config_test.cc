// navd.conf's [uwb] section (navd's UWB mode, paper 003): defaults, every key, and bad values
// named by file, line and key.
#include "hil/estimator/navd/navd_uwb_config.h"

#include <string>

#include <gtest/gtest.h>

#include "hil/estimator/navd/navd_config.h"

#include "navd_conf_text.h"

namespace hil::estimator {
namespace {

using test::Error;
using test::Load;

TEST(NavdUwbConfigTest, NoSectionNoUwbMode) {
  EXPECT_FALSE(Load("[input]\ngnss_device = /dev/ttyGPS\n").uwb.enabled());
}

TEST(NavdUwbConfigTest, EveryKey) {
  const NavdConfig c = Load(
      "[uwb]\ndevice = /dev/ttyUWB\nbaud = 115200\nformat = tag_frame0\n"
      "anchors_m = 0, 0, 20, 0, 20, 20, 0, 20\ncorrection = none\norigin_lat_deg = 30.25\n"
      "origin_lon_deg = 119.7\norigin_height_m = 30\ntime_zero_unix_ns = 1781078400000000000\n"
      "attitude_device = /dev/ttyWIT\nattitude_baud = 9600\nattitude_rate_hz = 20\n"
      "attitude_yaw_offset_deg = -90\nposition_std_m = 0.1\nyaw_std_deg = 2\n"
      "residual_std_m = 0.04\nresidual_distance_m = 3\nyaw_offset_std_deg = 4\n"
      "yaw_drift_std_dps = 0.02\n");
  const NavdUwbConfig& u = c.uwb;
  EXPECT_TRUE(u.enabled());
  EXPECT_EQ(u.device, "/dev/ttyUWB");
  EXPECT_EQ(u.baud, 115200);
  EXPECT_EQ(u.format, "tag_frame0");
  EXPECT_DOUBLE_EQ(u.anchors_m[5], 20);
  EXPECT_FALSE(u.correction);
  EXPECT_DOUBLE_EQ(u.origin_lat_deg, 30.25);
  EXPECT_EQ(u.time_zero_unix_ns, 1781078400000000000);
  EXPECT_EQ(u.attitude_device, "/dev/ttyWIT");
  EXPECT_DOUBLE_EQ(u.attitude_rate_hz, 20);
  EXPECT_DOUBLE_EQ(u.attitude_yaw_offset_deg, -90);
  EXPECT_DOUBLE_EQ(u.position_std_m, 0.1);
  EXPECT_DOUBLE_EQ(u.yaw_std_deg, 2);
  EXPECT_DOUBLE_EQ(u.residual_std_m, 0.04);
  EXPECT_DOUBLE_EQ(u.residual_distance_m, 3);
  EXPECT_DOUBLE_EQ(u.yaw_offset_std_deg, 4);
  EXPECT_DOUBLE_EQ(u.yaw_drift_std_dps, 0.02);
}

TEST(NavdUwbConfigTest, DefaultsArePaper003s) {
  const NavdUwbConfig u = Load("[uwb]\ndevice = /dev/ttyUWB\n").uwb;
  EXPECT_EQ(u.baud, 921600);
  EXPECT_EQ(u.format, "tdoa");
  EXPECT_TRUE(u.correction);
  EXPECT_DOUBLE_EQ(u.anchors_m[0], -10);
  EXPECT_TRUE(u.attitude_device.empty());
}

TEST(NavdUwbConfigTest, BadValuesNameFileLineAndKey) {
  EXPECT_EQ(Error("[uwb]\nformat = lec\n"),
            "n.conf:2: [uwb] format: unknown format 'lec' (known: tdoa, tag_frame0)");
  EXPECT_NE(
      Error("[uwb]\n\nanchors_m = 1, 2, 3\n").find("n.conf:3: [uwb] anchors_m: expected eight"),
      std::string::npos);
  EXPECT_NE(Error("[uwb]\nbaud = 12345\n").find("n.conf:2: [uwb] baud: unsupported baud rate"),
            std::string::npos);
  EXPECT_NE(Error("[uwb]\ntime_zero_unix_ns = -5\n").find("[uwb] time_zero_unix_ns"),
            std::string::npos);
  EXPECT_NE(Error("[uwb]\norigin_lat_deg = 91\n").find("out of range"), std::string::npos);
  EXPECT_EQ(Error("[uwb]\nanchor = 1\n"), "n.conf:2: [uwb] anchor: unknown key");
}

}  // namespace
}  // namespace hil::estimator

#include "hil/estimator/navd/navd_imu_config.h"

#include <string>

#include <gtest/gtest.h>

#include "hil/estimator/navd/navd_config.h"

#include "navd_conf_text.h"

namespace hil::estimator {
namespace {

using test::Error;
using test::Load;

TEST(NavdImuConfigTest, DefaultsAreTheSerialMcu) {
  const NavdConfig c = Load("[input]\nimu_device = /dev/ttyIMU\n");
  EXPECT_EQ(c.imu.source, "serial");
  EXPECT_FALSE(c.imu.from_can());
  EXPECT_EQ(c.imu.source_address, 0xE2);
  EXPECT_EQ(c.imu_format, "mcu");
}

TEST(NavdImuConfigTest, CanSourceWithAddress) {
  const NavdConfig c = Load(
      "[imu]\nsource = can\ncan_interface = vcan0\nsource_address = 0xE3\n[filter]\nmode = ekf\n");
  EXPECT_TRUE(c.imu.from_can());
  EXPECT_EQ(c.imu.can_interface, "vcan0");
  EXPECT_EQ(c.imu.source_address, 0xE3);
  EXPECT_EQ(c.mode(), NavMode::kEkf);  // an IMU mode without imu_device: the IMU is on CAN
  EXPECT_EQ(
      Load("[imu]\nsource = can\ncan_interface = can0\nsource_address = 17\n").imu.source_address,
      17);
  EXPECT_EQ(
      Load("[imu]\nsource = can\ncan_interface = can0\nsource_address = any\n").imu.source_address,
      -1);
}

TEST(NavdImuConfigTest, RazorTextFormat) {
  const NavdConfig c = Load(
      "[input]\nimu_device = /dev/ttyIMU\nimu_format = razor_text\n[imu]\nrazor_gnss_latency_s = "
      "0.25\n");
  EXPECT_EQ(c.imu_format, "razor_text");
  EXPECT_DOUBLE_EQ(c.imu.razor_gnss_latency_s, 0.25);
}

TEST(NavdImuConfigTest, ClearErrors) {
  EXPECT_EQ(Error("[imu]\nsource = usb\n"),
            "n.conf:2: [imu] source: unknown IMU source 'usb' (known: serial, can)");
  EXPECT_EQ(Error("[imu]\nsource = can\n"),
            "n.conf:2: [imu] source: source = can needs [imu] can_interface (e.g. vcan0)");
  EXPECT_EQ(Error("[imu]\ncan_interface = vcan 0\n"),
            "n.conf:2: [imu] can_interface: must be a network interface name such as vcan0 or "
            "can0, got 'vcan 0'");
  EXPECT_EQ(Error("[imu]\nsource = can\ncan_interface = vcan0\nsource_address = 254\n"),
            "n.conf:4: [imu] source_address: source address 254 out of range [0, 253]");
  EXPECT_EQ(Error("[imu]\nsource_address = E2\n"),
            "n.conf:2: [imu] source_address: expected a J1939 source address (0 … 253, decimal or "
            "0x hex) or 'any', got 'E2'");
  EXPECT_EQ(
      Error("[imu]\nsource = can\ncan_interface = vcan0\n[input]\nimu_device = /dev/ttyIMU\n"),
      "n.conf:2: [imu] source: source = can reads the IMU from [imu] can_interface; remove [input] "
      "imu_device");
  EXPECT_EQ(Error("[imu]\ncan_interface = vcan0\n"),
            "n.conf:2: [imu] can_interface: is only read with [imu] source = can");
  EXPECT_EQ(Error("[imu]\nrazor_gnss_latency_s = -1\n"),
            "n.conf:2: [imu] razor_gnss_latency_s: value -1 out of range [0, 2]");
  EXPECT_EQ(Error("[imu]\nrate = 10\n"), "n.conf:2: [imu] rate: unknown key");
}

}  // namespace
}  // namespace hil::estimator

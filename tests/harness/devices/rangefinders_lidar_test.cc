// The rangefinders and lidar rows (paper 001's range sensors) as run devices: a scenario with the
// greenhouse library piece gets four rangefinders and the LiDAR on their own ptys, casting against
// the scenario's greenhouse.
#include <unistd.h>

#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rangefinder/benewake_codec.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {
namespace {

TEST(DeviceSetRangeSensors, FourRangefindersAndTheLidarOnPtys) {
  const Scenario s = ParseScenario(
      "name: gh\norigin: {lat_deg: 32.0, lon_deg: 118.8}\n"
      "include: [greenhouse/seed001_greenhouse.yaml]\n",
      "gh.yaml");
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("hil_gh_devices_" + std::to_string(::getpid())))
          .string();
  std::filesystem::create_directories(dir + "/captures");
  {
    DeviceSet set = BuildDevices(s, 1, dir);
    ASSERT_NE(set.world, nullptr);
    ASSERT_EQ(set.devices.size(), 1u + 4u + 1u);  // gps0, four rangefinders, the LiDAR
    for (const char* link : {"ttyRF_RF", "ttyRF_RR", "ttyRF_LF", "ttyRF_LR", "ttyLIDAR"}) {
      EXPECT_TRUE(std::filesystem::is_symlink(dir + "/" + link)) << link;
    }
    Device& rf = *set.devices[1];
    EXPECT_EQ(rf.name(), "rf_right_front");
    EXPECT_EQ(rf.baud(0), 115200);
    // rows run north from (0, 0): aisle 0's centre line is x = −0.9; at (−0.9, 10) facing north
    // the right-front unit (0.25 m right of the centre) sees ridge 0's side x = −0.3 at 0.35 m
    TruthSample truth;
    truth.t = rf.next_event_time();
    truth.p_NB_N_m = Eigen::Vector3d(-0.9, 10, 0);
    truth.q_NB =
        Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
    DeviceOutput out;
    rf.OnEvent(truth, out);
    ASSERT_EQ(out.serial.size(), 1u);
    const auto f = rangefinder::DecodeDataFields(out.serial[0].bytes);
    EXPECT_NEAR(f.dist, 35, 3);
    EXPECT_EQ(set.devices[5]->name(), "lidar");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

// Which receiver navd reads (harness/scenario/navd_gnss_source.h): with a `zed_f9p:` rover navd's
// generated configuration names the rover's link at its UART1 rate (not the gnss receiver's), the
// run waits for navd on the rover's link only, the raw-fix baseline reads the rover's fixes and
// navd's lever arm is the rover's antenna; `navd_input: false` keeps the gnss receiver; navd's
// multi_gnss mode with a rover that feeds it is refused.
#include "hil/harness/scenario/navd_gnss_source.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/harness/devices/device_kind.h"
#include "hil/harness/devices/navd_conf.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

// A GNSS + IMU navd (ekf) with the rig's receiver on ttyGPS and a rover on ttyF9P at 115200 Bd,
// its antenna 0.5 m left of the rig's.
constexpr const char* kScenario =
    "name: t\n"
    "duration_s: 20\n"
    "origin: {lat_deg: 45.75, lon_deg: 126.63, height_m: 150}\n"
    "gnss: {profile: rtk, baud: 115200, antenna_lever_arm_m: [1.2, 0.0, 2.8]}\n"
    "mcu: {profile: industrial-mems, link: ttyIMU, baud: 115200}\n"
    "estimator: {navd_mode: ekf}\n"
    "rtk_base: {offset_enu_m: [1200, 1600, 3]}\n"
    "zed_f9p:\n"
    "  antenna_lever_arm_m: [1.2, 0.5, 2.8]\n"
    "  config: {CFG-UART1-BAUDRATE: 115200}\n";

std::string NavdConf(const Scenario& s, const std::string& dir) {
  WriteNavdConfig(dir + "/navd.conf", s, dir + "/" + s.gnss.link);
  std::ifstream in(dir + "/navd.conf");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> NavdLinks(const Scenario& s) {
  std::vector<std::string> links;
  for (const DeviceKind* k : DeviceKinds()) {
    if (!k->navd_links) continue;
    for (const std::string& l : k->navd_links(s)) links.push_back(l);
  }
  return links;
}

class NavdGnssSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir() + "/navd_gnss_source_" + std::to_string(::getpid());
    std::filesystem::create_directories(dir_ + "/captures");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string dir_;
};

TEST_F(NavdGnssSourceTest, NavdReadsTheRoverNotTheGnssReceiver) {
  const Scenario s = ParseScenario(kScenario, "s.yaml");
  EXPECT_TRUE(NavdReadsRover(s));
  const std::string conf = NavdConf(s, dir_);
  EXPECT_NE(conf.find("gnss_device = " + dir_ + "/ttyF9P\n"), std::string::npos) << conf;
  EXPECT_NE(conf.find("gnss_baud = 115200\n"), std::string::npos) << conf;
  EXPECT_EQ(conf.find("ttyGPS"), std::string::npos) << conf;  // never both receivers
  // navd's antenna is the rover's, relative to the IMU board
  const Eigen::Vector3d lever = Eigen::Vector3d(1.2, 0.5, 2.8) - s.mcu.config.mounting.p_BI_B_m;
  std::ostringstream line;
  line << "lever_arm_m = " << lever.x() << ", " << lever.y() << ", " << lever.z() << "\n";
  EXPECT_NE(conf.find(line.str()), std::string::npos) << conf;
  EXPECT_EQ(NavdLinks(s), (std::vector<std::string>{"ttyIMU", "ttyF9P"}));
}

TEST_F(NavdGnssSourceTest, TheRawFixBaselineReadsTheRover) {
  const Scenario s = ParseScenario(kScenario, "s.yaml");
  const DeviceSet set = BuildDevices(s, 1, dir_);
  ASSERT_NE(set.rover, nullptr);
  EXPECT_EQ(set.fix_sources.size(), 2u);  // the rig's receiver and the rover
  EXPECT_EQ(set.fix_sources.front()(), &set.rover->last_fix());
  EXPECT_EQ(NavdAntennaB(s).y(), 0.5);
}

TEST_F(NavdGnssSourceTest, NavdInputFalseKeepsTheGnssReceiver) {
  const Scenario s = ParseScenario(Joined(kScenario, "  navd_input: false\n"), "s.yaml");
  EXPECT_FALSE(NavdReadsRover(s));
  const std::string conf = NavdConf(s, dir_);
  EXPECT_NE(conf.find("gnss_device = " + dir_ + "/ttyGPS\n"), std::string::npos) << conf;
  EXPECT_EQ(conf.find("ttyF9P"), std::string::npos) << conf;
  EXPECT_EQ(NavdLinks(s), (std::vector<std::string>{"ttyGPS", "ttyIMU"}));
  const DeviceSet set = BuildDevices(s, 1, dir_);
  EXPECT_NE(set.fix_sources.front()(), &set.rover->last_fix());
  EXPECT_EQ(NavdAntennaB(s).y(), 0.0);
}

TEST_F(NavdGnssSourceTest, MultiGnssWithARoverFeedingNavdIsRefused) {
  std::string text = kScenario;
  text.replace(text.find("navd_mode: ekf"), 14, "navd_mode: multi_gnss");
  try {
    ParseScenario(text, "s.yaml");
    FAIL() << "multi_gnss with a rover feeding navd was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("navd_input"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hil::harness

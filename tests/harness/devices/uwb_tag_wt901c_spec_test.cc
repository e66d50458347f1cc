// The scenario's `uwb:` and `wt901c:` sections (harness/src/devices/uwb_tag/, wt901c/), the
// devices they create and navd.conf's [uwb] section for navd_mode uwb.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hil/harness/devices/navd_conf.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/report/run_outputs.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

constexpr const char* kBase =
    "name: t\n"
    "origin: {lat_deg: 30.2566, lon_deg: 119.7275}\n";

TEST(ScenarioPaper003Test, NoSectionsNoDevices) {
  const Scenario s = ParseScenario(kBase, "s.yaml");
  EXPECT_FALSE(s.uwb.enabled);
  EXPECT_FALSE(s.wt901c.enabled);
}

TEST(ScenarioPaper003Test, SectionsAndDefaults) {
  const Scenario s = ParseScenario(
      Joined(kBase,
             "uwb: {rate_hz: 10, output: both, anchors_m: [0, 0, 20, 0, 20, 20, 0, 20],\n"
             "      nlos_zones: [{centre_m: [3, 4], radius_m: 2, bias_m: 0.5}]}\n"
             "wt901c: {baud: 115200, rate_hz: 50}\n"
             "estimator: {navd_mode: uwb}\n"),
      "s.yaml");
  ASSERT_TRUE(s.uwb.enabled);
  EXPECT_EQ(s.uwb.link, "ttyUWB");
  EXPECT_EQ(s.uwb.config.baud, 921600);
  EXPECT_DOUBLE_EQ(s.uwb.config.rate_hz, 10);
  EXPECT_EQ(s.uwb.config.output, uwb::UwbOutput::kBoth);
  EXPECT_DOUBLE_EQ(s.uwb.config.p_W_anchor_m[2].y(), 20);
  EXPECT_DOUBLE_EQ(s.uwb.config.tag_height_m, 1.6);
  ASSERT_EQ(s.uwb.config.errors.nlos_zones.size(), 1u);
  EXPECT_DOUBLE_EQ(s.uwb.config.errors.nlos_zones[0].centre_W_m.y(), 4);
  ASSERT_TRUE(s.wt901c.enabled);
  EXPECT_EQ(s.wt901c.config.baud_code, 6);   // 115200
  EXPECT_EQ(s.wt901c.config.rrate_code, 8);  // 50 Hz
  EXPECT_EQ(s.estimator.navd_mode, NavdMode::kUwb);
}

void ExpectError(const std::string& text, const std::string& field, const std::string& fragment) {
  try {
    ParseScenario(Joined(kBase, text), "s.yaml");
    FAIL() << "expected a ScenarioError";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ScenarioPaper003Test, BadValuesNameTheirField) {
  ExpectError("uwb: {rate_hz: 100}\n", "uwb.rate_hz", "100");
  ExpectError("uwb: {anchors_m: [0, 0, 1, 1, 2, 2, 0, 5]}\n", "uwb.anchors_m", "collinear");
  ExpectError("uwb: {anchors_m: [0, 0, 1]}\n", "uwb.anchors_m", "8 numbers");
  ExpectError("uwb: {output: dwm}\n", "uwb.output", "tag_frame0");
  ExpectError("uwb: {white_sigma_m: [-1, 0]}\n", "uwb.white_sigma_m", "within");
  ExpectError("wt901c: {baud: 12345}\n", "wt901c.baud", "BAUD");
  ExpectError("wt901c: {rate_hz: 7}\n", "wt901c.rate_hz", "RRATE");
  ExpectError("wt901c: {link: a/b}\n", "wt901c.link", "plain file name");
}

TEST(ScenarioPaper003Test, DevicesLinksAndNavdConf) {
  const Scenario s = ParseScenario(Joined(kBase,
                                          "uwb: {output: tdoa}\nwt901c: {}\n"
                                          "estimator: {navd_mode: uwb}\n"),
                                   "s.yaml");
  const std::string dir =
      (std::filesystem::temp_directory_path() / "hil_uwb_tag_wt901c_spec_test").string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/captures");
  {
    const DeviceSet set = BuildDevices(s, 1, dir);
    ASSERT_EQ(set.devices.size(), 3u);  // gps0, uwb, wt901c
    EXPECT_EQ(set.devices[1]->name(), "uwb");
    EXPECT_EQ(set.devices[1]->baud(0), 921600);
    EXPECT_EQ(set.devices[2]->name(), "wt901c");
    EXPECT_EQ(set.devices[2]->baud(0), 9600);
    EXPECT_TRUE(std::filesystem::is_symlink(dir + "/ttyUWB"));
    EXPECT_TRUE(std::filesystem::is_symlink(dir + "/ttyWIT"));
  }
  WriteNavdConfig(dir + "/navd.conf", s, dir + "/ttyGPS");
  std::stringstream conf;
  conf << std::ifstream(dir + "/navd.conf").rdbuf();
  const std::string c = conf.str();
  EXPECT_NE(c.find("[uwb]\ndevice = " + dir + "/ttyUWB\nbaud = 921600\nformat = tdoa\n"),
            std::string::npos)
      << c;
  EXPECT_NE(c.find("anchors_m = -10, -10, 10, -10, 10, 10, -10, 10\n"), std::string::npos) << c;
  EXPECT_NE(c.find("attitude_device = " + dir + "/ttyWIT\nattitude_baud = 9600\n"),
            std::string::npos)
      << c;
  EXPECT_EQ(c.find("mode = uwb"), std::string::npos) << c;  // [uwb] selects the mode
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

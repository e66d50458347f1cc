// The scenario's `zed_f9p:` section (harness/src/devices/zed_f9p/): defaults, the RTK keys, the
// saved configuration by real key names, errors with their field, and the rover in the run's
// device set on its pty with the base's radio (the same seed as the base device's).
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/ubx_f9_config.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

namespace key = gnss::ubx::f9key;

constexpr const char* kBase =
    "name: t\n"
    "duration_s: 120\n"
    "origin: {lat_deg: 35.4796096, lon_deg: 50.5979765, height_m: 1312.0}\n"
    "rtk_base: {offset_enu_m: [1200, 1600, 3]}\n";

TEST(ScenarioZedF9pTest, NoSectionNoRover) {
  EXPECT_FALSE(ParseScenario(kBase, "s.yaml").zed_f9p.enabled);
}

TEST(ScenarioZedF9pTest, Defaults) {
  const Scenario s = ParseScenario(Joined(kBase, "zed_f9p: {}\n"), "s.yaml");
  ASSERT_TRUE(s.zed_f9p.enabled);
  EXPECT_EQ(s.zed_f9p.link, "ttyF9P");
  EXPECT_EQ(s.zed_f9p.corrections, F9pCorrections::kRadio);
  EXPECT_EQ(s.zed_f9p.config.rtk.time_to_fix_s, 10.0);
  EXPECT_EQ(s.zed_f9p.config.rtk.fixed_max_age_s, 5.0);
  EXPECT_EQ(s.zed_f9p.config.start_utc, s.start_utc);
  EXPECT_TRUE(s.zed_f9p.config.flash.empty());
}

TEST(ScenarioZedF9pTest, RtkKeysAndSavedConfiguration) {
  const Scenario s = ParseScenario(Joined(kBase,
                                          "zed_f9p:\n"
                                          "  corrections: host\n"
                                          "  antenna_lever_arm_m: [1.2, 0, 2.8]\n"
                                          "  time_to_fix_s: 30\n"
                                          "  fixed_max_age_s: 2\n"
                                          "  fixed_ppm: 2\n"
                                          "  config:\n"
                                          "    CFG-RATE-MEAS: 100\n"
                                          "    CFG-MSGOUT-UBX_NAV_PVT_UART1: 1\n"),
                                   "s.yaml");
  const ZedF9pDeviceSpec& f = s.zed_f9p;
  EXPECT_EQ(f.corrections, F9pCorrections::kHost);
  EXPECT_DOUBLE_EQ(f.config.model.p_BA_B_m.z(), 2.8);
  EXPECT_EQ(f.config.rtk.time_to_fix_s, 30.0);
  EXPECT_EQ(f.config.rtk.fixed_max_age_s, 2.0);
  EXPECT_EQ(f.config.rtk.fixed_ppm, 2.0);
  ASSERT_EQ(f.config.flash.size(), 2U);
  // in the table's order
  EXPECT_EQ(f.config.flash[0], (std::pair<std::uint32_t, std::uint64_t>{key::kRateMeas, 100}));
  EXPECT_EQ(f.config.flash[1], (std::pair<std::uint32_t, std::uint64_t>{key::kNavPvtUart1, 1}));
}

void ExpectError(const std::string& text, const std::string& field, const std::string& fragment) {
  try {
    ParseScenario(text, "s.yaml");
    FAIL() << "expected a ScenarioError";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ScenarioZedF9pTest, BadValuesNameTheirField) {
  ExpectError(
      "name: t\nduration_s: 10\norigin: {lat_deg: 35, lon_deg: 50, height_m: 0}\nzed_f9p: {}\n",
      "zed_f9p.corrections", "needs an rtk_base");
  ExpectError(Joined(kBase, "zed_f9p: {config: {CFG-RATE-MEAS: 10}}\n"),
              "zed_f9p.config.CFG-RATE-MEAS", "");
  ExpectError(Joined(kBase, "zed_f9p: {config: {CFG-FOO: 1}}\n"), "zed_f9p.config.CFG-FOO", "");
  ExpectError(Joined(kBase, "zed_f9p: {corrections: ntrip}\n"), "zed_f9p.corrections", "");
}

TEST(ScenarioZedF9pTest, MovingBaseKeys) {
  const Scenario s = ParseScenario(
      "name: t\nduration_s: 10\norigin: {lat_deg: 35, lon_deg: 50, height_m: 0}\n"
      "zed_f9p:\n"
      "  corrections: moving_base\n"
      "  antenna_lever_arm_m: [1.2, 0.6, 2.8]\n"
      "  moving_base_antenna_m: [1.2, -0.6, 2.8]\n"
      "  moving_base_baud: 230400\n"
      "  heading_valid_max_acc_deg: 2\n"
      "  time_to_fix_per_km_s: 0.5\n",
      "s.yaml");
  const ZedF9pDeviceSpec& f = s.zed_f9p;
  EXPECT_EQ(f.corrections, F9pCorrections::kMovingBase);
  ASSERT_TRUE(f.config.moving_base.has_value()) << "no rtk_base needed";
  EXPECT_DOUBLE_EQ(f.config.moving_base->p_BA_B_m.y(), -0.6);
  EXPECT_EQ(f.config.moving_base->baud, 230400);
  EXPECT_EQ(f.config.heading_valid_max_acc_deg, 2.0);
  EXPECT_EQ(f.config.rtk.time_to_fix_per_km_s, 0.5);
  ExpectError(
      "name: t\nduration_s: 10\norigin: {lat_deg: 35, lon_deg: 50, height_m: 0}\n"
      "zed_f9p: {corrections: moving_base, antenna_lever_arm_m: [0, 0, 0.05]}\n",
      "zed_f9p.moving_base_antenna_m", "0.1 m apart");
}

TEST(ScenarioZedF9pTest, TheRunHasTheRoverOnItsPty) {
  const Scenario s = ParseScenario(Joined(kBase, "zed_f9p: {}\n"), "s.yaml");
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("hil_zed_f9p_" + std::to_string(::getpid())))
          .string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/captures");
  {
    const DeviceSet set = BuildDevices(s, 1, dir);
    ASSERT_EQ(set.devices.size(), 3u);  // gps0, base0, f9p0
    EXPECT_EQ(set.devices[2]->name(), "f9p0");
    EXPECT_EQ(set.devices[2]->baud(0), 38400);
    EXPECT_EQ(set.rover, set.devices[2].get());
    EXPECT_TRUE(std::filesystem::is_symlink(dir + "/ttyF9P"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

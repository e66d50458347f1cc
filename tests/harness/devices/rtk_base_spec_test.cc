// The scenario's `rtk_base:` section (harness/src/devices/rtk_base/): defaults, every
// key, the base placed by an ENU offset from the origin, errors with the field, and the device
// with its pty (RUN_DIR/ttyRTCM) in the run's device set.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/geodesy.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

constexpr const char* kBase =
    "name: t\n"
    "duration_s: 120\n"
    "origin: {lat_deg: 35.4796096, lon_deg: 50.5979765, height_m: 1312.0}\n";

TEST(ScenarioRtkBaseTest, NoSectionNoBase) {
  EXPECT_FALSE(ParseScenario(kBase, "s.yaml").rtk_base.enabled);
}

TEST(ScenarioRtkBaseTest, DefaultsPutTheBaseAtTheOrigin) {
  const Scenario s = ParseScenario(Joined(kBase, "rtk_base: {}\n"), "s.yaml");
  ASSERT_TRUE(s.rtk_base.enabled);
  const rtk::RtkBaseConfig& c = s.rtk_base.config;
  EXPECT_EQ(s.rtk_base.link, "ttyRTCM");
  EXPECT_NEAR(c.lat_deg, 35.4796096, 1e-12);
  EXPECT_NEAR(c.height_m, 1312.0, 1e-6);
  EXPECT_EQ(c.msm, rtcm3::MsmKind::kMsm7);
  EXPECT_EQ(c.station_message, 1006);
  EXPECT_EQ(c.baud, 38400);
  EXPECT_EQ(c.start_utc, s.start_utc);
  EXPECT_EQ(c.radio.loss_probability, 0.0);
}

TEST(ScenarioRtkBaseTest, EveryKey) {
  const Scenario s = ParseScenario(
      Joined(kBase,
             "rtk_base:\n"
             "  link: ttyCORR\n"
             "  station_id: 4095\n"
             "  offset_enu_m: [1200, 1600, 3]\n"
             "  antenna_height_m: 1.5\n"
             "  msm: 4\n"
             "  station_message: 1005\n"
             "  obs_rate_hz: 2\n"
             "  station_interval_s: 30\n"
             "  output_lag_s: 0.1\n"
             "  baud: 19200\n"
             "  tx_buffer_bytes: 1024\n"
             "  radio: {bytes_per_s: 2000, latency_s: 0.2, loss_probability: 0.1,\n"
             "          outages: [{start_s: 60, end_s: 90}]}\n"
             "  observables: {elevation_mask_deg: 15, zenith_tropo_m: 2.0, vertical_iono_l1_m: 4,\n"
             "                phase_noise_m: 0.003}\n"),
      "s.yaml");
  const rtk::RtkBaseConfig& c = s.rtk_base.config;
  EXPECT_EQ(s.rtk_base.link, "ttyCORR");
  EXPECT_EQ(c.station_id, 4095);
  // 2 km from the origin (ENU offset through the truth's local frame)
  const Eigen::Vector3d d = gnss::EcefFromGeodetic(c.lat_deg, c.lon_deg, c.height_m) -
                            gnss::EcefFromGeodetic(35.4796096, 50.5979765, 1312.0);
  EXPECT_NEAR(d.norm(), std::sqrt(1200.0 * 1200 + 1600 * 1600 + 9), 1e-3);
  EXPECT_EQ(c.msm, rtcm3::MsmKind::kMsm4);
  EXPECT_EQ(c.station_message, 1005);
  EXPECT_DOUBLE_EQ(c.obs_rate_hz, 2);
  EXPECT_EQ(c.station_interval, std::chrono::seconds(30));
  EXPECT_EQ(c.output_lag, std::chrono::milliseconds(100));
  EXPECT_EQ(c.baud, 19200);
  EXPECT_EQ(s.rtk_base.tx_buffer_bytes, 1024u);
  EXPECT_DOUBLE_EQ(c.radio.bytes_per_s, 2000);
  EXPECT_EQ(c.radio.latency, std::chrono::milliseconds(200));
  EXPECT_DOUBLE_EQ(c.radio.loss_probability, 0.1);
  ASSERT_EQ(c.radio.outages.size(), 1u);
  EXPECT_EQ(c.radio.outages[0].end, TimeFromSeconds(90));
  EXPECT_DOUBLE_EQ(c.observables.elevation_mask_deg, 15);
  EXPECT_DOUBLE_EQ(c.observables.vertical_iono_l1_m, 4);
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

TEST(ScenarioRtkBaseTest, BadValuesNameTheirField) {
  ExpectError("rtk_base: {msm: 5}\n", "rtk_base.msm", "4 (MSM4) or 7");
  ExpectError("rtk_base: {station_message: 1004}\n", "rtk_base.station_message", "");
  ExpectError("rtk_base: {position: {lat_deg: 1, lon_deg: 2}, offset_enu_m: [0, 0, 0]}\n",
              "rtk_base.position", "not both");
  ExpectError("rtk_base: {offset_enu_m: [300000, 0, 0]}\n", "rtk_base.offset_enu_m", "200 km");
  ExpectError("rtk_base: {radio: {outages: [{start_s: 50, end_s: 40}]}}\n",
              "rtk_base.radio.outages[0].end_s", "after start_s");
  ExpectError("rtk_base: {radio: {los_probability: 0.1}}\n", "rtk_base.radio.los_probability", "");
  ExpectError("rtk_base: {link: a/b}\n", "rtk_base.link", "plain file name");
}

TEST(ScenarioRtkBaseTest, TheRunHasTheBaseOnItsPty) {
  const Scenario s = ParseScenario(Joined(kBase, "rtk_base: {station_id: 7}\n"), "s.yaml");
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("hil_rtk_base_" + std::to_string(::getpid())))
          .string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/captures");
  {
    const DeviceSet set = BuildDevices(s, 1, dir);
    ASSERT_EQ(set.devices.size(), 2u);  // gps0 (the default receiver), base0
    EXPECT_EQ(set.devices[1]->name(), "base0");
    EXPECT_EQ(set.devices[1]->baud(0), 38400);
    EXPECT_TRUE(std::filesystem::is_symlink(dir + "/ttyRTCM"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

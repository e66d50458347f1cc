// The scenario's `mcu:` section (harness/src/devices/mcu/) and the device set it
// creates.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/mcu/mcu_device.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

constexpr const char* kBase =
    "name: t\n"
    "origin: {lat_deg: 35.0, lon_deg: 50.0}\n"
    "gnss: {rate_hz: 2}\n";

TEST(ScenarioMcuTest, NoSectionNoBoard) {
  EXPECT_FALSE(ParseScenario(kBase, "s.yaml").mcu.enabled);
}

TEST(ScenarioMcuTest, TheDefaultScenarioCarriesTheRazorBoardAtTenTimesTheGpsRate) {
  const Scenario s = LoadDefaultScenario();
  ASSERT_TRUE(s.mcu.enabled);
  EXPECT_EQ(s.mcu.config.profile.name, "razor-v13");
  EXPECT_DOUBLE_EQ(s.mcu.config.imu_rate_hz, 10.0 * s.gnss.rate_hz);
  EXPECT_EQ(s.estimator.navd_mode, NavdMode::kEkf);
}

TEST(ScenarioMcuTest, DefaultsFollowSeed000) {
  const Scenario s = ParseScenario(std::string(kBase) + "mcu: {}\n", "s.yaml");
  ASSERT_TRUE(s.mcu.enabled);
  EXPECT_EQ(s.mcu.link, "ttyIMU");
  EXPECT_EQ(s.mcu.config.profile.name, "razor-v13");
  EXPECT_EQ(s.mcu.config.baud, 57600);
  EXPECT_DOUBLE_EQ(s.mcu.config.imu_rate_hz, 20.0);  // 10 × the 2 Hz GNSS rate
  EXPECT_EQ(s.mcu.config.start_utc, s.start_utc);
  EXPECT_EQ(s.mcu.config.format, mcu::SerialFormat::kBinary);
  EXPECT_FALSE(s.mcu.config.can.enabled);
}

TEST(ScenarioMcuTest, LatencyAndRebootAreDurationsReadFromSeconds) {
  const Scenario d = ParseScenario(std::string(kBase) + "mcu: {}\n", "s.yaml");
  EXPECT_EQ(d.mcu.config.output_lag, std::chrono::microseconds(500));
  EXPECT_EQ(d.mcu.config.reboot, std::chrono::milliseconds(200));
  const Scenario s = ParseScenario(
      std::string(kBase) + "mcu: {output_latency_s: 0.0007, reboot_s: 1.5}\n", "s.yaml");
  EXPECT_EQ(s.mcu.config.output_lag, std::chrono::microseconds(700));
  EXPECT_EQ(s.mcu.config.reboot, std::chrono::milliseconds(1500));
}

TEST(ScenarioMcuTest, ReadsEveryKey) {
  const Scenario s = ParseScenario(
      std::string(kBase) +
          "mcu:\n"
          "  profile: tactical\n"
          "  baud: 230400\n"
          "  link: ttyMCU\n"
          "  format: razor-v19\n"
          "  imu_rate_hz: 100\n"
          "  mag_rate_hz: 20\n"
          "  crystal_ppm: -30\n"
          "  jitter_us: 15\n"
          "  lever_arm_m: [0.1, 0.2, 1.5]\n"
          "  mounting_rpy_deg: [0, 0, 90]\n"
          "  magnetic: {field_enu_uT: [1, 2, -3], hard_iron_uT: [4, 5, 6]}\n"
          "  vibration: [{frequency_hz: 25, accel_amplitude_mps2: [1, 2, 3]}]\n"
          "  temperature: {start_c: 10, rate_c_per_h: 5}\n"
          "  can: {source_address: 0x81, priority: 2, ssi2_every: 10, latency_s: 0.002}\n"
          "  faults:\n"
          "    - {kind: reset, start_s: 30}\n"
          "    - {kind: stuck_sensor, start_s: 5, duration_s: 2, sensor: gyro}\n",
      "s.yaml");
  const mcu::McuConfig& c = s.mcu.config;
  EXPECT_EQ(c.profile.name, "tactical");
  EXPECT_EQ(c.baud, 230400);
  EXPECT_EQ(s.mcu.link, "ttyMCU");
  EXPECT_EQ(c.format, mcu::SerialFormat::kRazorV19);
  EXPECT_DOUBLE_EQ(c.imu_rate_hz, 100);
  EXPECT_DOUBLE_EQ(c.mag_rate_hz, 20);
  EXPECT_DOUBLE_EQ(c.crystal_ppm, -30);
  EXPECT_DOUBLE_EQ(c.jitter_us, 15);
  EXPECT_DOUBLE_EQ(c.mounting.p_BI_B_m.z(), 1.5);
  EXPECT_NEAR((c.mounting.q_BI * Eigen::Vector3d::UnitX()).y(), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.magnetic.hard_iron_I_uT.y(), 5);
  ASSERT_EQ(c.vibration.size(), 1u);
  EXPECT_DOUBLE_EQ(c.vibration[0].accel_amplitude_mps2.z(), 3);
  EXPECT_DOUBLE_EQ(c.temperature_rate_c_per_h, 5);
  EXPECT_TRUE(c.can.enabled);
  EXPECT_EQ(c.can.address.source_address, 0x81);
  EXPECT_EQ(c.can.address.priority, 2);
  EXPECT_EQ(c.can.ssi2_every, 10);
  ASSERT_EQ(c.faults.size(), 2u);
  EXPECT_EQ(c.faults[0].kind, mcu::FaultKind::kReset);
  EXPECT_EQ(c.faults[1].sensor, "gyro");
}

void ExpectError(const std::string& mcu_text, const std::string& field,
                 const std::string& fragment) {
  try {
    ParseScenario(std::string(kBase) + mcu_text, "s.yaml");
    FAIL() << "expected a ScenarioError";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ScenarioMcuTest, ExampleScenarioLoads) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  const Scenario s = LoadScenario(std::string(src) + "/vectors/mcu/seed000_razor_imu.yaml");
  EXPECT_TRUE(s.mcu.enabled);
  EXPECT_DOUBLE_EQ(s.mcu.config.imu_rate_hz, 10.0);
  EXPECT_DOUBLE_EQ(s.mcu.config.mounting.p_BI_B_m.z(), 1.5);
  EXPECT_TRUE(s.mcu.config.can.enabled);
}

TEST(ScenarioMcuTest, BadValuesNameTheirField) {
  ExpectError("mcu: {profil: razor-v13}\n", "mcu.profil", "did you mean 'profile'");
  ExpectError("mcu: {profile: adxl}\n", "mcu.profile", "razor-v13");
  ExpectError("mcu: {faults: [{kind: drop_frames, start_s: 1}]}\n", "mcu.faults[0].duration_s",
              "positive");
  ExpectError("mcu: {link: a/b}\n", "mcu.link", "plain file name");
}

TEST(ScenarioMcuTest, BuildDevicesAddsTheBoardWithItsLink) {
  const Scenario s = ParseScenario(std::string(kBase) + "mcu: {link: ttyIMU}\n", "s.yaml");
  const std::string dir =
      (std::filesystem::temp_directory_path() / "hil_scenario_mcu_test").string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/captures");
  {
    const DeviceSet set = BuildDevices(s, 1, dir);
    ASSERT_EQ(set.devices.size(), 2u);
    EXPECT_EQ(set.devices[1]->name(), "mcu");
    EXPECT_EQ(set.devices[1]->baud(0), 57600);
    ASSERT_EQ(set.endpoints[1].size(), 1u);
    EXPECT_EQ(set.links.back().first, "ttyIMU");
    EXPECT_TRUE(std::filesystem::is_symlink(dir + "/ttyIMU"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

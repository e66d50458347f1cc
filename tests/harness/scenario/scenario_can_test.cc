// The scenario's `can` section (harness/src/scenario/scenario_can.cc).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/estimator/navd/navd_config.h"
#include "hil/harness/devices/navd_conf.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/report/run_outputs.h"
#include "hil/harness/run/can_run.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

constexpr const char* kBase = "name: t\norigin: {lat_deg: 35.4796096, lon_deg: 50.5979765}\n";

TEST(ScenarioCanTest, NoSectionMeansNoCanLink) {
  const Scenario s = ParseScenario(kBase, "t.yaml");
  EXPECT_TRUE(s.can.interface.empty());
  EXPECT_FALSE(s.can.fd);
}

TEST(ScenarioCanTest, ReadsInterfaceAndFd) {
  const Scenario s = ParseScenario(Joined(kBase, "can: {interface: vcan0, fd: true}\n"), "t.yaml");
  EXPECT_EQ(s.can.interface, "vcan0");
  EXPECT_TRUE(s.can.fd);
}

TEST(ScenarioCanTest, BadValuesNameFileLineAndField) {
  for (const char* bad : {"can: {interface: /dev/can0}\n", "can: {interface: vcan0, bitrate: 5}\n",
                          "can: {fd: true}\n", "can: {interface: averyveryverylongname0}\n"}) {
    SCOPED_TRACE(bad);
    try {
      ParseScenario(Joined(kBase, bad), "t.yaml");
      FAIL() << "expected a ScenarioError";
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find("t.yaml:3"), std::string::npos) << e.what();
    }
  }
}

constexpr const char* kCanImu =
    "mcu: {profile: razor-v13, can: {enabled: true, source_address: 17}}\n"
    "can: {interface: vcan0, imu_to_estimator: true}\n"
    "estimator: {navd_mode: ekf, output: n2k_socketcan}\n";

TEST(ScenarioCanTest, ImuToEstimatorAndBusOutput) {
  const Scenario s = ParseScenario(Joined(kBase, kCanImu), "t.yaml");
  EXPECT_TRUE(s.can.imu_to_estimator);
  EXPECT_EQ(s.estimator.output, EstimatorOutput::kN2kSocketcan);
}

TEST(ScenarioCanTest, WhatNeedsTheBusIsChecked) {
  const std::pair<const char*, const char*> bad[] = {
      {"mcu: {profile: razor-v13}\ncan: {interface: vcan0, imu_to_estimator: true}\n",
       "t.yaml:4: can.imu_to_estimator"},
      {"can: {interface: vcan0, imu_to_estimator: true}\n", "t.yaml:3: can.imu_to_estimator"},
      {"estimator: {output: n2k_socketcan}\n", "t.yaml:3: estimator.output"}};
  for (const auto& [text, where] : bad) {
    SCOPED_TRACE(text);
    try {
      ParseScenario(Joined(kBase, text), "t.yaml");
      FAIL() << "expected a ScenarioError";
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
    }
  }
}

// the navd.conf the harness writes for the CAN chain is one navd accepts, reading the IMU from CAN
TEST(ScenarioCanTest, GeneratedNavdConfigReadsTheImuFromCan) {
  const Scenario s = ParseScenario(Joined(kBase, kCanImu), "t.yaml");
  const std::string dir = ::testing::TempDir() + "/scenario_can_test";
  std::filesystem::create_directories(dir);
  WriteNavdConfig(dir + "/navd.conf", s, dir + "/ttyGPS");
  const auto c = estimator::NavdConfig::FromFile(estimator::ConfigFile::Load(dir + "/navd.conf"));
  EXPECT_TRUE(c.imu.from_can());
  EXPECT_EQ(c.imu.can_interface, "vcan0");
  EXPECT_EQ(c.imu.source_address, 17);
  EXPECT_TRUE(c.imu_device.empty());
  EXPECT_EQ(c.mode(), estimator::NavMode::kEkf);
  EXPECT_EQ(c.can_interface, "vcan0");  // NMEA 2000 back onto the bus
  EXPECT_EQ(c.json_path, "-");          // JSON on stdout: the harness reads its health object
  std::filesystem::remove_all(dir);
}

TEST(ScenarioCanTest, VirtualModeIsRefusedForAnImuOnCan) {
  const Scenario s = ParseScenario(Joined(kBase, kCanImu), "t.yaml");
  RunOptions opt;
  opt.mode = RunMode::kVirtual;
  try {
    CheckCanRunMode(s, opt);
    FAIL() << "virtual mode must be refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--mode realtime"), std::string::npos) << e.what();
  }
  opt.mode = RunMode::kRealtime;
  EXPECT_NO_THROW(CheckCanRunMode(s, opt));
  opt.mode = RunMode::kVirtual;
  opt.emulate_only = true;
  EXPECT_NO_THROW(CheckCanRunMode(s, opt));
}

TEST(ScenarioCanTest, ShippedCanScenarioLoads) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  const Scenario s = LoadScenario(std::string(src) + "/vectors/scenarios/vcan/can_imu.yaml");
  EXPECT_TRUE(s.can.imu_to_estimator);
  EXPECT_EQ(s.can.interface, "vcan0");
  EXPECT_TRUE(s.mcu.config.can.enabled);
  EXPECT_EQ(s.mcu.config.can.address.source_address, 0xE2);
}

// the fault campaign's CAN scenario: can_imu.yaml's chain (included) with a can_reorder fault and
// criteria on navd's CAN counter
TEST(ScenarioCanTest, ShippedCanReorderFaultScenarioLoads) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  const Scenario s =
      LoadScenario(std::string(src) + "/vectors/scenarios/vcan/fault_can_reorder.yaml");
  EXPECT_EQ(s.name, "fault_can_reorder");
  EXPECT_TRUE(s.can.imu_to_estimator);  // from can_imu.yaml
  EXPECT_EQ(s.estimator.output, EstimatorOutput::kN2kSocketcan);
  ASSERT_EQ(s.faults.faults.size(), 1u);
  EXPECT_EQ(s.faults.faults[0].kind, FaultKind::kCanReorder);
  EXPECT_GT(s.faults.faults[0].Param("probability", 0), 0.0);
  EXPECT_LT(ToSeconds(s.faults.faults[0].end), s.duration_s);
  bool unpaired = false;
  for (const Criterion& c : s.criteria) unpaired = unpaired || c.metric == "navd.imu_can_unpaired";
  EXPECT_TRUE(unpaired);
}

}  // namespace
}  // namespace hil::harness

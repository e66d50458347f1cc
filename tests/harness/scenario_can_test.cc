// The scenario's `can` section (harness/src/scenario_can.cc).
#include <gtest/gtest.h>

#include "hil/harness/scenario.h"
#include "hil/harness/yaml_reader.h"

namespace hil::harness {
namespace {

constexpr const char* kBase = "name: t\norigin: {lat_deg: 35.4796096, lon_deg: 50.5979765}\n";

TEST(ScenarioCanTest, NoSectionMeansNoCanLink) {
  const Scenario s = ParseScenario(kBase, "t.yaml");
  EXPECT_TRUE(s.can.interface.empty());
  EXPECT_FALSE(s.can.fd);
}

TEST(ScenarioCanTest, ReadsInterfaceAndFd) {
  const Scenario s = ParseScenario(std::string(kBase) + "can: {interface: vcan0, fd: true}\n", "t.yaml");
  EXPECT_EQ(s.can.interface, "vcan0");
  EXPECT_TRUE(s.can.fd);
}

TEST(ScenarioCanTest, BadValuesNameFileLineAndField) {
  for (const char* bad : {"can: {interface: /dev/can0}\n", "can: {interface: vcan0, bitrate: 5}\n", "can: {fd: true}\n",
                          "can: {interface: averyveryverylongname0}\n"}) {
    SCOPED_TRACE(bad);
    try {
      ParseScenario(std::string(kBase) + bad, "t.yaml");
      FAIL() << "expected a ScenarioError";
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find("t.yaml:3"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace hil::harness

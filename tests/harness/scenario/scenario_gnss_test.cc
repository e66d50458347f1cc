// The scenario's gnss section (harness/src/scenario/scenario_gnss.cc): several receivers, faults,
// profiles.
#include <cmath>

#include <gtest/gtest.h>

#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

constexpr const char* kMinimal = "name: t\norigin: {lat_deg: 35.0, lon_deg: 50.0}\n";

TEST(ScenarioGnssTest, DefaultIsOneNeo5mOnTtyGps) {
  const Scenario s = ParseScenario(kMinimal, "s.yaml");
  ASSERT_EQ(s.gnss.receivers.size(), 1u);
  EXPECT_EQ(s.gnss.receivers[0].link, "ttyGPS");
  EXPECT_EQ(s.gnss.profile, "neo-5m");
  EXPECT_EQ(s.gnss.baud, 9600);
  EXPECT_EQ(s.gnss.start, gnss::StartKind::kHot);
}

TEST(ScenarioGnssTest, ThreeReceiversOnACircleFiveMetresApart) {
  // seed 000: three receivers on a 3 m circle, 5.2 m apart
  const Scenario s =
      ParseScenario(std::string(kMinimal) +
                        "gnss: {count: 3, array_radius_m: 3.0, antenna_lever_arm_m: [0, 0, 1.2]}\n",
                    "s.yaml");
  ASSERT_EQ(s.gnss.receivers.size(), 3u);
  EXPECT_EQ(s.gnss.receivers[0].link, "ttyGPS");
  EXPECT_EQ(s.gnss.receivers[1].link, "ttyGPS1");
  EXPECT_EQ(s.gnss.receivers[2].link, "ttyGPS2");
  for (int i = 0; i < 3; ++i) {
    const auto& a = s.gnss.receivers[static_cast<std::size_t>(i)].p_BA_B_m;
    const auto& b = s.gnss.receivers[static_cast<std::size_t>((i + 1) % 3)].p_BA_B_m;
    EXPECT_NEAR((a - b).norm(), 5.196, 0.01);
    EXPECT_NEAR(a.z(), 1.2, 1e-12);
  }
  EXPECT_EQ(s.gnss.model.p_BA_B_m, s.gnss.receivers[0].p_BA_B_m);
}

TEST(ScenarioGnssTest, ExplicitReceiversFaultsAndStart) {
  const Scenario s =
      ParseScenario(std::string(kMinimal) +
                        "gnss:\n"
                        "  start: cold\n"
                        "  receivers:\n"
                        "    - {link: gpsA, antenna_lever_arm_m: [1, 0, 1]}\n"
                        "    - {link: gpsB, antenna_lever_arm_m: [-1, 0, 1]}\n"
                        "  faults:\n"
                        "    - {kind: outage, start_s: 10, end_s: 20}\n"
                        "    - {kind: step, start_s: 30, end_s: 31, offset_m: [2, 0, 0]}\n",
                    "s.yaml");
  ASSERT_EQ(s.gnss.receivers.size(), 2u);
  EXPECT_EQ(s.gnss.link, "gpsA");
  EXPECT_EQ(s.gnss.start, gnss::StartKind::kCold);
  ASSERT_EQ(s.gnss.faults.size(), 2u);
  EXPECT_EQ(s.gnss.faults[0].kind, gnss::GnssFault::Kind::kOutage);
  EXPECT_EQ(s.gnss.faults[1].offset_N_m.x(), 2.0);
}

TEST(ScenarioGnssTest, RtkProfileDefaults) {
  const Scenario s = ParseScenario(std::string(kMinimal) + "gnss: {profile: rtk}\n", "s.yaml");
  EXPECT_EQ(s.gnss.baud, 115200);
  EXPECT_EQ(s.gnss.rate_hz, 10.0);
  EXPECT_LT(s.gnss.model.horizontal_sigma_m, 0.02);
}

TEST(ScenarioGnssTest, RefusesRatesAboveTheReceiverAndBadFaults) {
  for (const std::string bad :
       {"gnss: {rate_hz: 10}\n", "gnss: {faults: [{kind: outage, start_s: 5, end_s: 2}]}\n",
        "gnss: {faults: [{kind: jam}]}\n", "gnss: {receivers: [{link: a}, {link: a}]}\n"}) {
    EXPECT_THROW(ParseScenario(std::string(kMinimal) + bad, "s.yaml"), ScenarioError) << bad;
  }
}

}  // namespace
}  // namespace hil::harness

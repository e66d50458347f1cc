#include "hil/harness/scenario/fault_timeline.h"

#include <cstdlib>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/faults/byte_faults.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

constexpr const char* kBase = "name: t\nduration_s: 100\norigin: {lat_deg: 35.0, lon_deg: 50.0}\n";

Scenario Parse(const std::string& faults) { return ParseScenario(Joined(kBase, faults), "s.yaml"); }

void ExpectError(const std::string& faults, int line, const std::string& field,
                 const std::string& fragment) {
  try {
    Parse(faults);
    FAIL() << "expected a ScenarioError for:\n" << faults;
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(FaultTimelineTest, ParsesEveryKindWithItsParameters) {
  const Scenario s = Parse(
      "faults:\n"
      "  - {kind: gnss_outage, start_s: 40, end_s: 55}\n"
      "  - {kind: gnss_glitch, start_s: 70, end_s: 72, north_m: 8, east_m: -3}\n"
      "  - {kind: byte_corruption, start_s: 10, end_s: 20, probability: 0.01, link: ttyGPS}\n"
      "  - {kind: frame_drop, start_s: 30, end_s: 35}\n"
      "  - {kind: mcu_reset, start_s: 90}\n"
      "  - {kind: baud_mismatch, start_s: 95, end_s: 99, baud: 4800}\n");
  ASSERT_EQ(s.faults.faults.size(), 6u);
  const auto outages = s.faults.OfKind(FaultKind::kGnssOutage);
  ASSERT_EQ(outages.size(), 1u);
  EXPECT_DOUBLE_EQ(ToSeconds(outages[0].start), 40.0);
  EXPECT_DOUBLE_EQ(ToSeconds(outages[0].end), 55.0);
  const Fault& glitch = s.faults.faults[1];
  EXPECT_DOUBLE_EQ(glitch.Param("north_m", 0), 8.0);
  EXPECT_DOUBLE_EQ(glitch.Param("east_m", 0), -3.0);
  EXPECT_DOUBLE_EQ(glitch.Param("up_m", 99), 0.0) << "declared parameters get their defaults";
  EXPECT_EQ(s.faults.faults[2].link, "ttyGPS");
  EXPECT_DOUBLE_EQ(s.faults.faults[3].Param("probability", 0), 1.0);
  EXPECT_EQ(s.faults.faults[4].start, s.faults.faults[4].end) << "mcu_reset is instantaneous";
  EXPECT_TRUE(s.faults.ActiveAt(FaultKind::kByteCorruption, TimeFromSeconds(15), "ttyGPS"));
  EXPECT_FALSE(s.faults.ActiveAt(FaultKind::kByteCorruption, TimeFromSeconds(15), "ttyIMU"))
      << "other link";
  EXPECT_FALSE(s.faults.ActiveAt(FaultKind::kByteCorruption, TimeFromSeconds(20), "ttyGPS"))
      << "end is exclusive";
  EXPECT_TRUE(s.faults.ActiveAt(FaultKind::kFrameDrop, TimeFromSeconds(30), "anything"))
      << "no link: every link";
}

TEST(FaultTimelineTest, ErrorsNameLineAndField) {
  ExpectError("faults:\n  - {kind: gnss_outgae, start_s: 1, end_s: 2}\n", 5, "faults[0].kind",
              "unknown fault kind");
  ExpectError("faults:\n  - {kind: gnss_outage, start_s: 5, end_s: 2}\n", 5, "faults[0].end_s",
              "must be after");
  ExpectError("faults:\n  - {kind: gnss_outage, start_s: 5, end_s: 200}\n", 5, "faults[0].end_s",
              "out of range");
  ExpectError("faults:\n  - kind: frame_drop\n    start_s: 1\n    end_s: 2\n    probability: 1.5\n",
              8, "faults[0].probability", "out of range");
  ExpectError("faults:\n  - {kind: gnss_outage, start_s: 1, end_s: 2, link: ttyGPS}\n", 5,
              "faults[0].link", "unknown key");
  ExpectError("faults:\n  - {kind: gnss_outage, end_s: 2}\n", 5, "faults[0]", "start_s");
  ExpectError("faults:\n  - {kind: gnss_outage, start_s: 1}\n", 5, "faults[0]", "end_s");
}

// A closed-loop scenario around `faults` (its faults list starts on line 9).
std::string ClosedLoop(const std::string& faults) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return Joined(kBase,
                "vehicle: {model: diff_drive}\nclosed_loop:\n  path_file: ", src ? src : "..",
                "/vectors/paths/ab_line_east_300m.path\n  controller: x\n", faults);
}

void ExpectClosedLoopError(const std::string& faults, const std::string& field,
                           const std::string& fragment) {
  try {
    ParseScenario(ClosedLoop(faults), "s.yaml");
    FAIL() << "expected a ScenarioError for:\n" << faults;
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.line(), 9) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(FaultTimelineTest, ClosedLoopActuatorFaultsAndTheirErrors) {
  const Scenario s = ParseScenario(
      ClosedLoop(
          "faults:\n"
          "  - {kind: command_latency, start_s: 10, end_s: 40, latency_s: 0.15, jitter_s: 0.1}\n"
          "  - {kind: actuator_saturation, start_s: 20, end_s: 30, max_wheel_speed_radps: 4}\n"
          "  - {kind: actuator_stuck, start_s: 20, end_s: 23}\n"),
      "s.yaml");
  ASSERT_EQ(s.faults.faults.size(), 3u);
  EXPECT_EQ(s.faults.faults[0].kind, FaultKind::kCommandLatency);
  EXPECT_DOUBLE_EQ(s.faults.faults[0].Param("latency_s", 0), 0.15);
  EXPECT_DOUBLE_EQ(s.faults.faults[0].Param("jitter_s", 0), 0.1);
  EXPECT_DOUBLE_EQ(s.faults.faults[1].Param("max_wheel_speed_radps", 0), 4.0);
  EXPECT_EQ(s.faults.faults[2].kind, FaultKind::kActuatorStuck);
  EXPECT_DOUBLE_EQ(ToSeconds(s.faults.faults[2].end), 23.0);
  ExpectClosedLoopError(
      "faults:\n  - {kind: command_latency, start_s: 1, end_s: 2, latency_s: 3}\n",
      "faults[0].latency_s", "out of range");
  ExpectClosedLoopError(
      "faults:\n  - {kind: command_latency, start_s: 1, end_s: 2, jitter_s: -1}\n",
      "faults[0].jitter_s", "out of range");
  ExpectClosedLoopError(
      "faults:\n  - {kind: actuator_saturation, start_s: 1, end_s: 2, max_speed: 3}\n",
      "faults[0].max_speed", "unknown key");
  ExpectClosedLoopError("faults:\n  - {kind: actuator_stuck, start_s: 3}\n", "faults[0]", "end_s");
  ExpectClosedLoopError("faults:\n  - {kind: actuator_stuck, start_s: 3, end_s: 2}\n",
                        "faults[0].end_s", "must be after");
  // without a closed_loop section they would do nothing: refused
  ExpectError("faults:\n  - {kind: actuator_stuck, start_s: 3, end_s: 4}\n", 5, "faults[0].kind",
              "no closed_loop");
}

SerialMessage Msg(double t_s, const std::string& bytes) {
  SerialMessage m;
  m.t_ready = TimeFromSeconds(t_s);
  m.bytes = bytes;
  return m;
}

TEST(ByteFaultsTest, DropsAndCorruptsOnlyInsideTheirWindowsAndRepeatsWithTheSeed) {
  const Scenario s = Parse(
      "faults:\n"
      "  - {kind: frame_drop, start_s: 10, end_s: 20, probability: 1}\n"
      "  - {kind: byte_corruption, start_s: 30, end_s: 40, probability: 0.1}\n");
  const std::string payload(1000, 'A');
  ByteFaultInjector a(s.faults, 7), b(s.faults, 7), c(s.faults, 8);
  SerialMessage m = Msg(5, payload);
  EXPECT_TRUE(a.Apply(m, "ttyGPS"));
  EXPECT_EQ(m.bytes, payload) << "no fault active at 5 s";
  m = Msg(15, payload);
  EXPECT_FALSE(a.Apply(m, "ttyGPS"));
  EXPECT_EQ(a.messages_dropped(), 1u);
  SerialMessage ma = Msg(35, payload), mb = Msg(35, payload), mc = Msg(35, payload);
  b.Apply(mb = Msg(15, payload), "ttyGPS");  // same random stream position as a
  mb = Msg(35, payload);
  c.Apply(mc = Msg(15, payload), "ttyGPS");
  mc = Msg(35, payload);
  ASSERT_TRUE(a.Apply(ma, "ttyGPS"));
  ASSERT_TRUE(b.Apply(mb, "ttyGPS"));
  ASSERT_TRUE(c.Apply(mc, "ttyGPS"));
  std::size_t changed = 0;
  for (std::size_t i = 0; i < payload.size(); ++i) {
    if (ma.bytes[i] != 'A') {
      ++changed;
      const unsigned diff =
          static_cast<unsigned char>(ma.bytes[i]) ^ static_cast<unsigned char>('A');
      EXPECT_EQ(diff & (diff - 1), 0u) << "one bit flipped per corrupted byte";
    }
  }
  EXPECT_GT(changed, 60u);  // 10 % of 1000, binomial σ ≈ 9.5
  EXPECT_LT(changed, 140u);
  EXPECT_EQ(changed, a.bytes_corrupted());
  EXPECT_EQ(ma.bytes, mb.bytes) << "same seed, same corruption";
  EXPECT_NE(ma.bytes, mc.bytes) << "another seed, other corruption";
}

}  // namespace
}  // namespace hil::harness

// The steering ECU's side of ISO 11783-7 guidance against vectors/isobus/guidance_golden.txt: it
// decodes every Guidance System Command (ours and AgIsoStack++'s) and reproduces the bytes of
// every Machine Info and Wheel-based Speed frame marked check=both.
#include "hil/firmware_emu/actuator/isobus_guidance.h"

#include <gtest/gtest.h>

#include "isobus_golden_line.h"

namespace hil::actuator {
namespace {

using hil::test::IsobusGoldenLine;

CanFrame FrameOf(const IsobusGoldenLine& g) {
  CanFrame f;
  f.id = g.id;
  f.len = g.len;
  for (int i = 0; i < 8; ++i) f.data[i] = g.data[i];
  return f;
}

void ExpectSameBytes(const IsobusGoldenLine& g, const CanFrame& f) {
  EXPECT_EQ(f.id, g.id) << "line " << g.line_number;
  ASSERT_EQ(f.len, g.len) << "line " << g.line_number;
  for (int i = 0; i < g.len; ++i)
    EXPECT_EQ(f.data[i], g.data[i]) << "line " << g.line_number << " byte " << i;
}

void CheckCommand(const IsobusGoldenLine& g) {
  const J1939IdFields id = SplitJ1939Id(g.id);
  EXPECT_EQ(id.pgn, kPgnGuidanceSystemCommand);
  EXPECT_EQ(id.source, g.Int("sa"));
  EXPECT_EQ(id.destination, g.Int("da"));
  GuidanceSystemCommand cmd;
  const CommandFrameError err = DecodeGuidanceSystemCommand(FrameOf(g), cmd);
  const std::string& want = g.fields.at("error");
  if (want == "wrong_length") {
    EXPECT_EQ(err, CommandFrameError::kWrongLength) << "line " << g.line_number;
    return;
  }
  if (want == "out_of_range") {
    EXPECT_EQ(err, CommandFrameError::kCurvatureOutOfRange) << "line " << g.line_number;
    return;
  }
  ASSERT_EQ(err, CommandFrameError::kNone) << "line " << g.line_number;
  const double expected =
      g.fields.count("decoded_per_km") ? g.Num("decoded_per_km") : g.Num("curvature_per_km");
  EXPECT_NEAR(cmd.curvature_per_km, expected, 0.125) << "line " << g.line_number;
  EXPECT_EQ(static_cast<int>(cmd.status), g.Int("status")) << "line " << g.line_number;
}

void CheckMachineInfo(const IsobusGoldenLine& g) {
  if (g.fields.at("check") != "both") return;
  GuidanceMachineInfo m;
  m.estimated_curvature_per_km = g.Num("curvature_per_km");
  m.mechanical_system_lockout = static_cast<std::uint8_t>(g.Int("lockout"));
  m.steering_system_readiness = static_cast<std::uint8_t>(g.Int("readiness"));
  m.steering_input_position_status = static_cast<std::uint8_t>(g.Int("input_position"));
  m.request_reset_command_status = static_cast<std::uint8_t>(g.Int("reset"));
  m.guidance_limit_status = static_cast<std::uint8_t>(g.Int("limit"));
  m.exit_reason_code = static_cast<std::uint8_t>(g.Int("exit"));
  m.remote_engage_switch_status = static_cast<std::uint8_t>(g.Int("engage_switch"));
  const auto sa = static_cast<std::uint8_t>(g.Int("sa"));
  const auto da = static_cast<std::uint8_t>(g.Int("da"));
  ExpectSameBytes(g, EncodeGuidanceMachineInfo(Time{}, 3, sa, da, m));
}

void CheckWheelSpeed(const IsobusGoldenLine& g) {
  WheelBasedSpeedDistance w;
  w.speed_mps = g.Num("speed_mps");
  w.distance_m = g.Num("distance_m");
  w.max_time_of_tractor_power_min = static_cast<std::uint8_t>(g.Int("max_time_min"));
  w.direction = static_cast<std::uint8_t>(g.Int("direction"));
  w.key_switch = static_cast<std::uint8_t>(g.Int("key_switch"));
  w.implement_start_stop = static_cast<std::uint8_t>(g.Int("implement_start_stop"));
  w.operator_direction_reversed = static_cast<std::uint8_t>(g.Int("operator_direction_reversed"));
  ExpectSameBytes(
      g, EncodeWheelBasedSpeedDistance(Time{}, 3, static_cast<std::uint8_t>(g.Int("sa")), w));
}

TEST(IsobusGuidanceGolden, EcuSideAgreesWithEveryGoldenFrame) {
  const auto lines = hil::test::ReadIsobusGolden(hil::test::IsobusGoldenPath());
  ASSERT_GE(lines.size(), 20u);
  int commands = 0, infos = 0, speeds = 0;
  for (const auto& g : lines) {
    const int pgn = g.Int("pgn");
    if (pgn == 44288) {
      CheckCommand(g);
      ++commands;
    } else if (pgn == 44032) {
      CheckMachineInfo(g);
      ++infos;
    } else if (pgn == 65096) {
      CheckWheelSpeed(g);
      ++speeds;
    }
  }
  EXPECT_GE(commands, 10);
  EXPECT_GE(infos, 4);
  EXPECT_GE(speeds, 4);
}

TEST(IsobusGuidance, CurvatureScalingPinsTheRoundingRule) {
  EXPECT_EQ(EncodeCurvatureRaw(0.0), 32128);
  EXPECT_EQ(EncodeCurvatureRaw(-8032.0), 0);
  EXPECT_EQ(EncodeCurvatureRaw(-9000.0), 0);
  EXPECT_EQ(EncodeCurvatureRaw(8031.75), 64255);
  EXPECT_EQ(EncodeCurvatureRaw(1e9), 64255);
  EXPECT_EQ(EncodeCurvatureRaw(0.125), 32129);  // exactly half an LSB: away from zero
  EXPECT_EQ(EncodeCurvatureRaw(0.124), 32128);
  EXPECT_DOUBLE_EQ(CurvatureFromRaw(32505), 94.25);
}

TEST(IsobusGuidance, IdentifiersAreJ1939Pdu1AndPdu2) {
  EXPECT_EQ(MakeJ1939Id(3, kPgnGuidanceSystemCommand, 0x46, 0xFF), 0x0CADFF46u);
  EXPECT_EQ(MakeJ1939Id(3, kPgnGuidanceMachineInfo, 0x44, 0xFF), 0x0CACFF44u);
  EXPECT_EQ(MakeJ1939Id(3, kPgnWheelBasedSpeedDistance, 0x1C, 0x80), 0x0CFE481Cu);
  const J1939IdFields f = SplitJ1939Id(0x0CAD1C80);
  EXPECT_EQ(f.pgn, kPgnGuidanceSystemCommand);
  EXPECT_EQ(f.destination, 0x1C);
  EXPECT_EQ(f.source, 0x80);
  EXPECT_EQ(f.priority, 3);
}

}  // namespace
}  // namespace hil::actuator

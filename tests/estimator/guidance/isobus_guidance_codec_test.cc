// The guidance controller's side of ISO 11783-7 against vectors/isobus/guidance_golden.txt: it
// reproduces the bytes of every System Command marked check=both and decodes every Machine Info
// and Wheel-based Speed frame (ours and AgIsoStack++'s).
#include "hil/estimator/guidance/isobus_guidance_codec.h"

#include <gtest/gtest.h>

#include "../../firmware_emu/actuator/isobus_golden_line.h"

namespace hil::estimator::guidance {
namespace {

using hil::test::IsobusGoldenLine;

IsobusFrame FrameOf(const IsobusGoldenLine& g) {
  IsobusFrame f;
  f.id = g.id;
  f.len = g.len;
  f.data = g.data;
  return f;
}

void CheckCommand(const IsobusGoldenLine& g) {
  if (g.fields.at("check") != "both") return;
  SystemCommandAddress a;
  a.source = static_cast<std::uint8_t>(g.Int("sa"));
  a.destination = static_cast<std::uint8_t>(g.Int("da"));
  const IsobusFrame f =
      EncodeSystemCommand(a, g.Num("curvature_per_km"), static_cast<std::uint8_t>(g.Int("status")));
  EXPECT_EQ(f.id, g.id) << "line " << g.line_number;
  ASSERT_EQ(f.len, g.len) << "line " << g.line_number;
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(f.data[i], g.data[i]) << "line " << g.line_number << " byte " << i;
}

void CheckMachineInfo(const IsobusGoldenLine& g) {
  MachineInfo m;
  ASSERT_EQ(DecodeMachineInfo(FrameOf(g), m), IsobusDecodeResult::kOk) << "line " << g.line_number;
  EXPECT_EQ(m.source, g.Int("sa"));
  EXPECT_TRUE(m.curvature_valid);
  EXPECT_NEAR(m.estimated_curvature_per_km, g.Num("curvature_per_km"), 0.125)
      << "line " << g.line_number;
  EXPECT_EQ(m.mechanical_lockout, g.Int("lockout")) << "line " << g.line_number;
  EXPECT_EQ(m.readiness, g.Int("readiness")) << "line " << g.line_number;
  EXPECT_EQ(m.input_position_status, g.Int("input_position")) << "line " << g.line_number;
  EXPECT_EQ(m.request_reset, g.Int("reset")) << "line " << g.line_number;
  EXPECT_EQ(m.limit_status, g.Int("limit")) << "line " << g.line_number;
  EXPECT_EQ(m.exit_reason, g.Int("exit")) << "line " << g.line_number;
  EXPECT_EQ(m.remote_engage_switch, g.Int("engage_switch")) << "line " << g.line_number;
}

void CheckWheelSpeed(const IsobusGoldenLine& g) {
  WheelSpeedDistance w;
  ASSERT_EQ(DecodeWheelSpeedDistance(FrameOf(g), w), IsobusDecodeResult::kOk);
  EXPECT_TRUE(w.speed_valid && w.distance_valid);
  EXPECT_NEAR(w.speed_mps, g.Num("speed_mps"), 5e-4) << "line " << g.line_number;
  EXPECT_NEAR(w.distance_m, g.Num("distance_m"), 5e-4) << "line " << g.line_number;
  EXPECT_EQ(w.max_time_of_tractor_power_min, g.Int("max_time_min"));
  EXPECT_EQ(w.direction, g.Int("direction")) << "line " << g.line_number;
  EXPECT_EQ(w.key_switch, g.Int("key_switch"));
  EXPECT_EQ(w.implement_start_stop, g.Int("implement_start_stop"));
  EXPECT_EQ(w.operator_direction_reversed, g.Int("operator_direction_reversed"));
}

TEST(IsobusGuidanceCodecGolden, ControllerSideAgreesWithEveryGoldenFrame) {
  const auto lines = hil::test::ReadIsobusGolden(hil::test::IsobusGoldenPath());
  ASSERT_GE(lines.size(), 20u);
  int encoded = 0, decoded = 0;
  for (const auto& g : lines) {
    const int pgn = g.Int("pgn");
    if (pgn == 44288) {
      CheckCommand(g);
      if (g.fields.at("check") == "both") ++encoded;
    } else if (pgn == 44032) {
      CheckMachineInfo(g);
      ++decoded;
    } else if (pgn == 65096) {
      CheckWheelSpeed(g);
      ++decoded;
    }
  }
  EXPECT_GE(encoded, 7);
  EXPECT_GE(decoded, 10);
}

TEST(IsobusGuidanceCodec, RefusesOtherPgnsAndShortFrames) {
  IsobusFrame f;
  f.id = 0x0CADFF46;
  f.len = 8;
  MachineInfo m;
  EXPECT_EQ(DecodeMachineInfo(f, m), IsobusDecodeResult::kOtherPgn);
  f.id = 0x0CACFF1C;
  f.len = 5;
  EXPECT_EQ(DecodeMachineInfo(f, m), IsobusDecodeResult::kWrongLength);
  EXPECT_EQ(PgnOfId(0x0CFE481C), kPgnWheelSpeedDistance);
  EXPECT_EQ(PgnOfId(0x0CAD1C80), kPgnSystemCommand);
  EXPECT_DOUBLE_EQ(IsobusCurvatureFromLeft(0.1), -100.0);
}

}  // namespace
}  // namespace hil::estimator::guidance

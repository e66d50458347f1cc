// The differential-drive base's ROSArduinoBridge protocol: framing, codec and the session against
// vectors/base_serial/session_golden.tsv (replies byte for byte, watchdog included).
#include "hil/firmware_emu/actuator/base_serial_session.h"

#include <gtest/gtest.h>

#include "hil/firmware_emu/actuator/base_serial_codec.h"

#include "base_session_golden.h"

namespace hil::actuator {
namespace {

WheelMotorsConfig GoldenBase() {
  WheelMotorsConfig c;
  c.wheel_radius_m = 0.1;
  c.track_m = 0.5;
  c.encoder_counts_per_rev = 1200;
  c.time_constant_s = 0;
  c.max_wheel_accel_radps2 = 0;
  c.command_latency = Duration{0};
  c.command_timeout = std::chrono::milliseconds(2000);
  return c;
}

TEST(BaseSerialSession, AnswersTheGoldenSessionByteForByte) {
  const auto golden = hil::test::ReadBaseSessionGolden();
  ASSERT_GE(golden.size(), 15u);
  WheelMotors motors(GoldenBase());
  BaseSerialSession session(BaseSerialConfig{}, motors);
  for (const auto& e : golden) {
    DeviceOutput out;
    const Time t = TimeFromNs(e.t_ms * 1000000);
    session.OnHostBytes(t, e.host, out);
    if (e.reply.empty()) {
      EXPECT_TRUE(out.serial.empty()) << "line " << e.line_number;
      continue;
    }
    ASSERT_EQ(out.serial.size(), 1u) << "line " << e.line_number;
    EXPECT_EQ(out.serial[0].bytes, e.reply) << "line " << e.line_number;
    EXPECT_EQ(out.serial[0].t_ready, t);
  }
  EXPECT_EQ(motors.counters().watchdog_trips, 2u);  // 0 → 2000 ms and 3000 → 5000 ms
  EXPECT_EQ(session.overlong_lines(), 1u);
  EXPECT_EQ(session.counters().invalid, 1u);
}

TEST(BaseSerialCodec, ParsesArgumentsAsAtoiDoes) {
  BaseCommand c = ParseBaseCommand("m -12 7x");
  EXPECT_EQ(c.kind, BaseCommandKind::kMotorSpeeds);
  EXPECT_EQ(c.args[0], -12);
  EXPECT_EQ(c.args[1], 7);
  c = ParseBaseCommand("m abc");
  EXPECT_EQ(c.args[0], 0);
  c = ParseBaseCommand("u 20:12:0:50");
  EXPECT_EQ(c.kind, BaseCommandKind::kUpdatePid);
  EXPECT_EQ(c.arg_count, 4);
  EXPECT_EQ(c.args[3], 50);
  EXPECT_EQ(ParseBaseCommand("").kind, BaseCommandKind::kInvalid);
  EXPECT_EQ(ParseBaseCommand("z").kind, BaseCommandKind::kInvalid);
  EXPECT_EQ(FormatBaseEncoders(-5, 2147483647), "-5 2147483647\r\n");
}

TEST(BaseSerialSession, TicksPerFrameMapOntoWheelSpeed) {
  WheelMotors motors(GoldenBase());
  BaseSerialSession session(BaseSerialConfig{}, motors);
  // 40 ticks per 1/30 s frame at 1200 counts/rev = 1 rev/s.
  EXPECT_NEAR(session.RadpsFromTicksPerFrame(40), 2 * 3.14159265358979, 1e-12);
  EXPECT_EQ(session.TicksPerFrameFromRadps(2 * 3.14159265358979), 40);
}

}  // namespace
}  // namespace hil::actuator

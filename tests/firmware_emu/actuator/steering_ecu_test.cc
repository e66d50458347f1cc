// The emulated ISOBUS steering ECU: engage/disengage, lag, rate limit, ±limit, deadband, latency,
// watchdog and the refusal of bad commands, with expectations derived from its configuration.
#include "hil/firmware_emu/actuator/steering_ecu.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace hil::actuator {
namespace {

using std::chrono::milliseconds;
constexpr double kDegToRad = std::numbers::pi / 180.0;

// A Guidance System Command frame from SA 0x80 to the ECU (0x1C), built from the specification.
CanFrame Command(double curvature_per_km, int status, std::uint8_t sa = 0x80, int len = 8) {
  CanFrame f;
  f.id = 0x0CAD0000u | (0x1Cu << 8) | sa;
  f.len = static_cast<std::uint8_t>(len);
  const auto raw = static_cast<std::uint16_t>(std::lround((curvature_per_km + 8032.0) * 4.0));
  f.data = {};
  f.data[0] = static_cast<std::uint8_t>(raw & 0xFF);
  f.data[1] = static_cast<std::uint8_t>(raw >> 8);
  f.data[2] = static_cast<std::uint8_t>(0xFC | status);
  for (int i = 3; i < 8; ++i) f.data[i] = 0xFF;
  return f;
}

Time Ms(std::int64_t ms) { return TimeFromNs(ms * 1000000); }

SteeringEcuConfig Config() {
  SteeringEcuConfig c;
  c.wheelbase_m = 2.5;
  c.max_steer_deg = 35;
  c.max_steer_rate_dps = 40;
  c.time_constant_s = 0.15;
  c.deadband_deg = 0.05;
  c.command_latency = milliseconds(20);
  c.command_timeout = milliseconds(300);
  return c;
}

// Sends `curvature` every 100 ms from `from_ms` to `to_ms` (exclusive) at 2 m/s.
void Drive(SteeringEcu& ecu, double curvature, int status, int from_ms, int to_ms) {
  for (int t = from_ms; t < to_ms; t += 100) {
    ecu.AdvanceTo(Ms(t), 2.0);
    ecu.OnFrame(Ms(t), Command(curvature, status));
  }
  ecu.AdvanceTo(Ms(to_ms), 2.0);
}

TEST(SteeringEcu, EngagesAndSettlesOnTheCommandedCurvatureWithinTheDeadband) {
  SteeringEcu ecu(Config());
  Drive(ecu, 100.0, 1, 0, 3000);
  EXPECT_TRUE(ecu.engaged());
  EXPECT_EQ(ecu.exit_reason(), ExitReason::kAllClear);
  const double want = std::atan(0.1 * 2.5);  // κ = 100 km⁻¹ right
  EXPECT_NEAR(ecu.steer_angle_rad(), want, 0.05 * kDegToRad + 1e-9);
  EXPECT_GT(ecu.steer_angle_rad(), want - 0.05 * kDegToRad - 1e-9);
  EXPECT_NEAR(ecu.curvature_left_per_m(), -std::tan(ecu.steer_angle_rad()) / 2.5, 1e-15);
  const GuidanceMachineInfo m = ecu.machine_info();
  EXPECT_NEAR(m.estimated_curvature_per_km, 100.0, 0.5);
  EXPECT_EQ(m.exit_reason_code, 0);
  EXPECT_EQ(m.request_reset_command_status, 0);
  EXPECT_EQ(ecu.counters().commands_accepted, 30u);
  EXPECT_EQ(ecu.counters().engagements, 1u);
}

TEST(SteeringEcu, ACommandActsAtArrivalPlusLatencyAndRampsAtTheRateLimit) {
  SteeringEcu ecu(Config());
  ecu.OnFrame(Ms(0), Command(-200.0, 1));  // left, δ = atan(0.5) = 26.6° — far beyond r·τ = 6°
  ecu.AdvanceTo(Ms(20), 2.0);
  EXPECT_EQ(ecu.steer_angle_rad(), 0.0);
  ecu.AdvanceTo(Ms(120), 2.0);
  EXPECT_NEAR(ecu.steer_angle_rad(), -40.0 * kDegToRad * 0.1, 1e-12);
}

TEST(SteeringEcu, ClampsAtTheSteeringLimitAndReportsTheLimitStatus) {
  SteeringEcu ecu(Config());
  Drive(ecu, 1000.0, 1, 0, 4000);  // δ = atan(2.5) = 68° right > 35°
  EXPECT_NEAR(ecu.steer_angle_rad(), 35.0 * kDegToRad, 0.051 * kDegToRad);
  EXPECT_EQ(ecu.machine_info().guidance_limit_status, 2);
  Drive(ecu, -1000.0, 1, 4000, 8000);
  EXPECT_NEAR(ecu.steer_angle_rad(), -35.0 * kDegToRad, 0.051 * kDegToRad);
  EXPECT_EQ(ecu.machine_info().guidance_limit_status, 3);
}

TEST(SteeringEcu, DoesNotActOnAPositionErrorInsideTheDeadband) {
  SteeringEcu ecu(Config());
  Drive(ecu, 50.0, 1, 0, 3000);
  const double settled = ecu.steer_angle_rad();
  // 0.03° more steer is inside the 0.05° deadband around the settled angle.
  const double k = 1000.0 * std::tan(settled + 0.03 * kDegToRad) / 2.5;
  Drive(ecu, k, 1, 3000, 5000);
  EXPECT_EQ(ecu.steer_angle_rad(), settled);
}

TEST(SteeringEcu, WatchdogExitsAtLastArrivalPlusTimeoutAndDemandsAReset) {
  SteeringEcu ecu(Config());
  Drive(ecu, 100.0, 1, 0, 1000);  // last command arrives at 900 ms
  ecu.AdvanceTo(Ms(1199), 2.0);
  EXPECT_TRUE(ecu.engaged());
  ecu.AdvanceTo(Ms(1500), 2.0);
  EXPECT_FALSE(ecu.engaged());
  EXPECT_EQ(ecu.counters().watchdog_trips, 1u);
  EXPECT_EQ(ecu.counters().last_watchdog_trip, Ms(1200));
  EXPECT_EQ(ecu.exit_reason(), ExitReason::kRemoteCommandTimeout);
  EXPECT_EQ(ecu.machine_info().exit_reason_code, 5);
  EXPECT_EQ(ecu.machine_info().request_reset_command_status, 1);
  const double held = ecu.steer_angle_rad();
  Drive(ecu, -100.0, 1, 1500, 2000);  // "intended to steer" alone does not re-engage
  EXPECT_FALSE(ecu.engaged());
  EXPECT_EQ(ecu.steer_angle_rad(), held);
  Drive(ecu, 0.0, 0, 2000, 2200);  // "not intended to steer" clears the reset request
  EXPECT_EQ(ecu.machine_info().request_reset_command_status, 0);
  Drive(ecu, -100.0, 1, 2200, 2500);
  EXPECT_TRUE(ecu.engaged());
  EXPECT_EQ(ecu.counters().engagements, 2u);
}

TEST(SteeringEcu, RefusesAndCountsBadCommandsWithoutFeedingTheWatchdog) {
  SteeringEcu ecu(Config());
  Drive(ecu, 100.0, 1, 0, 500);                    // last good command at 400 ms
  ecu.OnFrame(Ms(500), Command(0.0, 1, 0x80, 3));  // wrong length
  ecu.OnFrame(Ms(550), Command(0.0, 1, 0x55));     // unknown source
  EXPECT_EQ(ecu.counters().wrong_length, 1u);
  EXPECT_EQ(ecu.counters().unknown_source, 1u);
  ecu.AdvanceTo(Ms(800), 2.0);
  EXPECT_EQ(ecu.exit_reason(), ExitReason::kRemoteCommandTimeout);  // 400 + 300 ms
  EXPECT_EQ(ecu.counters().last_watchdog_trip, Ms(700));

  SteeringEcu other(Config());
  Drive(other, 100.0, 1, 0, 500);
  CanFrame bad = Command(0.0, 1);
  bad.data[0] = 0xFF;
  bad.data[1] = 0xFF;  // raw 65535: not a curvature
  other.OnFrame(Ms(500), bad);
  other.AdvanceTo(Ms(600), 2.0);
  EXPECT_EQ(other.counters().out_of_range, 1u);
  EXPECT_FALSE(other.engaged());
  EXPECT_EQ(other.machine_info().exit_reason_code, 6);
  EXPECT_EQ(other.counters().watchdog_trips, 0u);
}

TEST(SteeringEcu, ExitsWhenTheSpeedLeavesTheEngageRange) {
  SteeringEcuConfig c = Config();
  c.max_engage_speed_mps = 5.0;
  SteeringEcu ecu(c);
  Drive(ecu, 10.0, 1, 0, 500);
  EXPECT_TRUE(ecu.engaged());
  ecu.AdvanceTo(Ms(600), 6.0);
  EXPECT_FALSE(ecu.engaged());
  EXPECT_EQ(ecu.machine_info().exit_reason_code, 24);
}

TEST(SteeringEcu, ResultDoesNotDependOnHowTimeIsSplit) {
  SteeringEcu coarse(Config()), fine(Config());
  for (int t = 0; t < 3000; t += 100) {
    const double k = 150.0 * std::sin(t * 1e-3);
    coarse.AdvanceTo(Ms(t), 2.0);
    coarse.OnFrame(Ms(t), Command(k, 1));
    for (int s = t - 99; s <= t; ++s)
      if (s > 0) fine.AdvanceTo(Ms(s), 2.0);
    fine.OnFrame(Ms(t), Command(k, 1));
  }
  coarse.AdvanceTo(Ms(3000), 2.0);
  for (int s = 2901; s <= 3000; ++s) fine.AdvanceTo(Ms(s), 2.0);
  EXPECT_NEAR(coarse.steer_angle_rad(), fine.steer_angle_rad(), 1e-12);
}

TEST(SteeringEcu, EmitsMachineInfoAndWheelSpeedEvery100ms) {
  SteeringEcu ecu(Config());
  DeviceOutput out;
  for (int i = 0; i < 3; ++i) {
    ecu.AdvanceTo(ecu.next_status_time(), 1.0);
    ecu.EmitStatus(1.0, 0.1 * i, out);
  }
  ASSERT_EQ(out.can.size(), 6u);
  EXPECT_EQ(out.can[0].id, 0x0CACFF1Cu);
  EXPECT_EQ(out.can[1].id, 0x0CFE481Cu);
  EXPECT_EQ(out.can[4].t, Ms(200));
  EXPECT_EQ(out.can[5].data[0], 0xE8);  // 1.000 m/s
  EXPECT_EQ(out.can[5].data[1], 0x03);
}

}  // namespace
}  // namespace hil::actuator

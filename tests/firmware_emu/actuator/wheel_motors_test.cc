// The emulated wheel motors: lag and acceleration limit in closed form, speed limit, encoder
// quantisation, slip, latency and the watchdog.
#include "hil/firmware_emu/actuator/wheel_motors.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "hil/firmware_emu/actuator/first_order_rate_limited.h"

namespace hil::actuator {
namespace {

using std::chrono::milliseconds;
Time Ms(std::int64_t ms) { return TimeFromNs(ms * 1000000); }

TEST(FirstOrderRateLimited, RampThenExponentialAndItsIntegral) {
  // r = 2/s, τ = 0.5 s, step of 3: ramp until the error is r·τ = 1, i.e. for 1 s.
  const LagStep ramp = AdvanceFirstOrderRateLimited(0.0, 3.0, 0.5, 2.0, 0.5);
  EXPECT_DOUBLE_EQ(ramp.x, 1.0);
  EXPECT_DOUBLE_EQ(ramp.integral, 0.25);
  const LagStep both = AdvanceFirstOrderRateLimited(0.0, 3.0, 0.5, 2.0, 2.0);
  EXPECT_NEAR(both.x, 3.0 - std::exp(-2.0), 1e-15);
  EXPECT_NEAR(both.integral, 1.0 + 3.0 * 1.0 - 0.5 * (1.0 - std::exp(-2.0)), 1e-14);
  double x = 0, integral = 0;  // the same in 2000 pieces
  for (int i = 0; i < 2000; ++i) {
    const LagStep s = AdvanceFirstOrderRateLimited(x, 3.0, 0.5, 2.0, 1e-3);
    x = s.x;
    integral += s.integral;
  }
  EXPECT_NEAR(x, both.x, 1e-12);
  EXPECT_NEAR(integral, both.integral, 1e-12);
}

WheelMotorsConfig Config() {
  WheelMotorsConfig c;
  c.wheel_radius_m = 0.1;
  c.track_m = 0.5;
  c.encoder_counts_per_rev = 1200;
  c.max_wheel_speed_radps = 20;
  c.max_wheel_accel_radps2 = 30;
  c.time_constant_s = 0.08;
  c.command_latency = milliseconds(5);
  c.command_timeout = milliseconds(2000);
  return c;
}

TEST(WheelMotors, ReachTheTargetThroughTheLagAndCountTheShaftAngle) {
  WheelMotors m(Config());
  for (int t = 0; t <= 3000; t += 100) m.Command(Ms(t), 10.0, 10.0);
  m.AdvanceTo(Ms(3000));
  EXPECT_NEAR(m.wheel_speed_radps(kLeftWheel), 10.0, 1e-6);
  EXPECT_NEAR(m.body_speed_mps(), 1.0, 1e-7);
  EXPECT_NEAR(m.body_yaw_rate_radps(), 0.0, 1e-12);
  // Angle: 10 rad/s for 2.995 s less what the ramp (10/30 s) and the lag (τ) cost.
  const LagStep s = AdvanceFirstOrderRateLimited(0.0, 10.0, 0.08, 30.0, 2.995);
  const double counts = s.integral / (2 * std::numbers::pi) * 1200;
  EXPECT_EQ(m.encoder_count(kLeftWheel), static_cast<std::int64_t>(std::floor(counts)));
  EXPECT_EQ(m.encoder_count(kLeftWheel), m.encoder_count(kRightWheel));
}

TEST(WheelMotors, ClampSpeedCommandsAndCountThem) {
  WheelMotors m(Config());
  m.Command(Ms(0), 50.0, -50.0);
  m.AdvanceTo(Ms(1500));
  EXPECT_NEAR(m.wheel_speed_radps(kLeftWheel), 20.0, 1e-3);
  EXPECT_NEAR(m.wheel_speed_radps(kRightWheel), -20.0, 1e-3);
  EXPECT_EQ(m.counters().saturated_commands, 1u);
  EXPECT_NEAR(m.body_yaw_rate_radps(), -2 * 20.0 * 0.1 / 0.5, 2e-3);
}

TEST(WheelMotors, SlipLowersGroundSpeedButNotTheEncoder) {
  WheelMotorsConfig c = Config();
  c.slip = {0.1, 0.0};
  WheelMotors m(c);
  for (int t = 0; t <= 2000; t += 100) m.Command(Ms(t), 5.0, 5.0);
  m.AdvanceTo(Ms(2000));
  EXPECT_NEAR(m.ground_speed_mps(kLeftWheel), 0.9 * 0.5, 1e-6);
  EXPECT_NEAR(m.ground_speed_mps(kRightWheel), 0.5, 1e-6);
  EXPECT_EQ(m.encoder_count(kLeftWheel), m.encoder_count(kRightWheel));
  EXPECT_GT(m.body_yaw_rate_radps(), 0.0);  // the slipping left wheel lags: the base turns left
}

// A skid-steered base (icr_expansion χ): the same wheel speeds turn it χ times more slowly than a
// differential drive, so its turning radius is χ times the one its controller computes.
TEST(WheelMotors, SkidSteerTurnsChiTimesWiderThanTheWheelSpeedsSay) {
  WheelMotorsConfig c = Config();
  c.icr_expansion = 1.5;
  WheelMotors skid(c), diff(Config());
  for (int t = 0; t <= 2000; t += 100) {
    skid.Command(Ms(t), 4.0, 6.0);
    diff.Command(Ms(t), 4.0, 6.0);
  }
  skid.AdvanceTo(Ms(2000));
  diff.AdvanceTo(Ms(2000));
  const double r_commanded = 0.5 / 2 * (0.6 + 0.4) / (0.6 - 0.4);  // 1.25 m
  EXPECT_NEAR(diff.body_speed_mps() / diff.body_yaw_rate_radps(), r_commanded, 1e-6);
  EXPECT_NEAR(skid.body_speed_mps() / skid.body_yaw_rate_radps(), 1.5 * r_commanded, 1e-6);
  EXPECT_EQ(skid.body_speed_mps(), diff.body_speed_mps());
  EXPECT_EQ(skid.encoder_count(kLeftWheel), diff.encoder_count(kLeftWheel));
}

TEST(WheelMotors, ACommandActsAfterTheLatency) {
  WheelMotors m(Config());
  m.Command(Ms(0), 10.0, 10.0);
  m.AdvanceTo(Ms(5));
  EXPECT_EQ(m.wheel_speed_radps(kLeftWheel), 0.0);
  m.AdvanceTo(Ms(15));
  EXPECT_NEAR(m.wheel_speed_radps(kLeftWheel), 30.0 * 0.010, 1e-12);  // on the acceleration limit
}

TEST(WheelMotors, WatchdogStopsTheWheelsAtLastCommandPlusTimeout) {
  WheelMotors m(Config());
  for (int t = 0; t <= 1000; t += 100) m.Command(Ms(t), 10.0, 10.0);
  m.AdvanceTo(Ms(2999));
  EXPECT_FALSE(m.stopped_by_watchdog());
  EXPECT_NEAR(m.wheel_speed_radps(kLeftWheel), 10.0, 1e-6);
  m.AdvanceTo(Ms(5000));
  EXPECT_TRUE(m.stopped_by_watchdog());
  EXPECT_EQ(m.counters().watchdog_trips, 1u);
  EXPECT_EQ(m.counters().last_watchdog_trip, Ms(3000));
  EXPECT_NEAR(m.wheel_speed_radps(kLeftWheel), 0.0, 1e-6);
  const std::int64_t parked = m.encoder_count(kLeftWheel);
  m.AdvanceTo(Ms(9000));
  EXPECT_EQ(m.encoder_count(kLeftWheel), parked);
  EXPECT_EQ(m.counters().watchdog_trips, 1u);  // once per loss
  m.Command(Ms(9000), 1.0, 1.0);
  EXPECT_FALSE(m.stopped_by_watchdog());
}

}  // namespace
}  // namespace hil::actuator

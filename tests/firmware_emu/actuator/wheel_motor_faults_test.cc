// The wheel motors' scripted faults: latency and seeded jitter (the same draws every run, the
// line's order kept), saturation (clamped targets, time clamped), a stuck drive (the output held).
#include "hil/firmware_emu/actuator/wheel_motor_faults.h"

#include <gtest/gtest.h>

#include "hil/firmware_emu/actuator/wheel_motors.h"

namespace hil::actuator {
namespace {

using std::chrono::milliseconds;
Time Ms(std::int64_t ms) { return TimeFromNs(ms * 1000000); }

WheelMotorsConfig Config(std::vector<WheelMotorFault> faults, std::uint64_t seed = 7) {
  WheelMotorsConfig c;
  c.max_wheel_speed_radps = 20;
  c.max_wheel_accel_radps2 = 30;
  c.time_constant_s = 0.08;
  c.command_latency = milliseconds(5);
  c.faults = std::move(faults);
  c.fault_seed = seed;
  return c;
}

WheelMotorFault Latency(std::int64_t from_ms, std::int64_t to_ms, std::int64_t lat_ms,
                        std::int64_t jitter_ms) {
  WheelMotorFault f;
  f.kind = WheelMotorFault::Kind::kCommandLatency;
  f.start = Ms(from_ms);
  f.end = Ms(to_ms);
  f.latency = milliseconds(lat_ms);
  f.jitter = milliseconds(jitter_ms);
  return f;
}

TEST(WheelMotorFaults, LatencyWithoutJitterDelaysExactlyInsideTheWindow) {
  WheelMotors m(Config({Latency(1000, 2000, 200, 0)}));
  m.Command(Ms(1000), 10.0, 10.0);  // acts at 1000 + 5 + 200 ms
  m.AdvanceTo(Ms(1204));
  EXPECT_EQ(m.wheel_speed_radps(kLeftWheel), 0.0);
  m.AdvanceTo(Ms(1215));
  EXPECT_NEAR(m.wheel_speed_radps(kLeftWheel), 30.0 * 0.010, 1e-12);
  m.Command(Ms(2000), 0.0, 0.0);  // the window is over: 5 ms only
  m.AdvanceTo(Ms(2005));
  EXPECT_EQ(m.target_speed_radps(kLeftWheel), 0.0);
  const WheelMotorFaultCounters& k = m.faults().counters()[0];
  EXPECT_EQ(k.events, 1u);
  EXPECT_EQ(k.added_latency_max, milliseconds(200));
}

TEST(WheelMotorFaults, JitterIsSeededBoundedAndKeepsTheLineInOrder) {
  WheelMotorFaults a({Latency(0, 100000, 50, 100)}, 42), b({Latency(0, 100000, 50, 100)}, 42),
      c({Latency(0, 100000, 50, 100)}, 43);
  Duration lo = Duration::max(), hi{};
  int differ = 0;
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const Duration d = a.AddedLatency(Ms(static_cast<std::int64_t>(i)), i);
    EXPECT_EQ(d, b.AddedLatency(Ms(static_cast<std::int64_t>(i)), i));  // same seed, same draw
    differ += d != c.AddedLatency(Ms(static_cast<std::int64_t>(i)), i) ? 1 : 0;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  EXPECT_GT(differ, 990);
  EXPECT_GE(lo, milliseconds(50));
  EXPECT_LT(hi, milliseconds(150));
  EXPECT_LT(lo, milliseconds(52));  // uniform over [50, 150) ms: 1000 draws reach both ends
  EXPECT_GT(hi, milliseconds(148));
  EXPECT_EQ(a.counters()[0].events, 1000u);
  // on the motors (10 Hz commands of rising speeds): a command never overtakes the one sent
  // before it, so the target in effect only rises
  WheelMotors m(Config({Latency(0, 10000, 0, 300)}));
  double seen = 0;
  for (int t = 0; t < 3000; ++t) {
    if (t % 100 == 0) m.Command(Ms(t), t / 100.0, 0.0);
    m.AdvanceTo(Ms(t));
    EXPECT_GE(m.target_speed_radps(kLeftWheel), seen) << t;
    seen = m.target_speed_radps(kLeftWheel);
  }
  EXPECT_EQ(m.counters().queue_overflow, 0u);
}

TEST(WheelMotorFaults, SaturationClampsTheTargetsAndCountsTheTime) {
  WheelMotorFault f;
  f.kind = WheelMotorFault::Kind::kSaturation;
  f.start = Ms(1000);
  f.end = Ms(3000);
  f.max_wheel_speed_radps = 4;
  WheelMotors m(Config({f}));
  for (int t = 0; t < 3000; t += 100) m.Command(Ms(t), 5.0, 5.0);
  m.AdvanceTo(Ms(2990));
  EXPECT_NEAR(m.wheel_speed_radps(kLeftWheel), 4.0, 1e-6);
  EXPECT_EQ(m.target_speed_radps(kLeftWheel), 5.0);  // what was commanded
  for (int t = 3000; t <= 5000; t += 100) m.Command(Ms(t), 5.0, 5.0);
  EXPECT_NEAR(m.wheel_speed_radps(kRightWheel), 5.0, 1e-6);
  EXPECT_EQ(m.counters().saturated_commands, 20u);  // 1000 ms … 2900 ms
  EXPECT_NEAR(m.counters().saturated_s, 2.0, 1e-9);
  EXPECT_NEAR(m.faults().counters()[0].clamped_s, 2.0, 1e-9);
  EXPECT_EQ(m.faults().counters()[0].events, 20u);
}

TEST(WheelMotorFaults, AStuckDriveHoldsItsOutputThenFollowsAgain) {
  WheelMotorFault f;
  f.kind = WheelMotorFault::Kind::kStuck;
  f.start = Ms(2000);
  f.end = Ms(3000);
  WheelMotors m(Config({f}));
  for (int t = 0; t < 2000; t += 100) m.Command(Ms(t), 10.0, 8.0);
  m.AdvanceTo(Ms(2000));
  const double left = m.wheel_speed_radps(kLeftWheel), right = m.wheel_speed_radps(kRightWheel);
  const std::int64_t counts = m.encoder_count(kLeftWheel);
  for (int t = 2000; t < 3000; t += 100) m.Command(Ms(t), 0.0, 0.0);
  m.AdvanceTo(Ms(2999));
  EXPECT_EQ(m.wheel_speed_radps(kLeftWheel), left);
  EXPECT_EQ(m.wheel_speed_radps(kRightWheel), right);
  // the wheels keep turning at the held speed: 0.999 s of it on the encoder
  EXPECT_NEAR(static_cast<double>(m.encoder_count(kLeftWheel) - counts),
              left * 0.999 / (2 * 3.141592653589793) * 1200, 1.0);
  for (int t = 3000; t < 5000; t += 100) m.Command(Ms(t), 0.0, 0.0);
  EXPECT_NEAR(m.wheel_speed_radps(kLeftWheel), 0.0, 1e-6);
  EXPECT_NEAR(m.faults().counters()[0].held_s, 1.0, 1e-9);
  EXPECT_EQ(m.faults().counters()[0].events, 10u);  // the commands of 2000 … 2900 ms
}

}  // namespace
}  // namespace hil::actuator

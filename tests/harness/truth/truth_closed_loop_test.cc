// The closed-loop parts plugged together without the scheduler: the CVODE truth, the guidance
// (estimator/guidance, fed with the true pose), the real command bytes and the emulated actuators.
// - Tractor: pure pursuit → Guidance System Command frames → the emulated steering ECU → its
//   road-wheel angle as the truth's steering input (10 ms grid); then the commands stop and the
//   ECU's watchdog exits.
// - Differential drive: pure pursuit → `m L R` lines → the ROSArduinoBridge session → the wheel
//   motors → speed and yaw rate as the truth's inputs; then the commands stop and the base's
//   auto-stop halts the vehicle.
// The truth's own actuator lags are made negligible so that the emulated actuators are the model.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "hil/estimator/guidance/base_serial_client.h"
#include "hil/estimator/guidance/isobus_guidance_codec.h"
#include "hil/estimator/guidance/path_file.h"
#include "hil/estimator/guidance/path_tracker.h"
#include "hil/firmware_emu/actuator/base_serial_session.h"
#include "hil/firmware_emu/actuator/steering_ecu.h"
#include "hil/truth/truth_integrator.h"

namespace hil::truth {
namespace {

namespace g = hil::estimator::guidance;
constexpr std::int64_t kGridNs = 10'000'000;  // truth command grid, 10 ms

g::VehiclePose2d PoseOf(const TruthSample& s) {
  g::VehiclePose2d p;
  p.p_EN_m = s.p_NB_N_m.head<2>();
  const Eigen::Vector3d x_N = s.q_NB * Eigen::Vector3d::UnitX();
  p.yaw_rad = std::atan2(x_N.y(), x_N.x());
  p.speed_mps = s.speed_mps;
  return p;
}

CanFrame ToBus(const g::IsobusFrame& f) {
  CanFrame c;
  c.id = f.id;
  c.len = f.len;
  for (int i = 0; i < 8; ++i) c.data[i] = f.data[i];
  return c;
}

TruthConfig Base(VehicleParams v, double start_north_m) {
  TruthConfig c;
  c.origin = {35.4796096, 50.5979765, 1300};
  c.vehicle = v;
  c.start_p_N_m = Eigen::Vector2d(0, start_north_m);
  c.heading_deg = 90;  // east, along the AB line
  c.external_commands = true;
  c.command_period_s = 1e-9 * kGridNs;
  return c;
}

TEST(ClosedLoopParts, TractorOverIsobusSettlesTracksAndExitsOnCommandLoss) {
  VehicleParams v = VehicleParams::Tractor();
  v.steer_lag_s = 1e-3;  // the ECU is the steering actuator
  v.max_steer_rate_dps = 1000;
  v.max_steer_deg = 40;
  TruthIntegrator truth(Base(v, -1.0));  // 1 m right of the line
  actuator::SteeringEcuConfig ecu_cfg;
  ecu_cfg.wheelbase_m = v.wheelbase_m;
  actuator::SteeringEcu ecu(ecu_cfg);
  const g::PlannedPath line =
      g::ParsePathText("hil-path 1\nab_line a_m=0,0 b_m=400,0\n", "ab_line");
  g::PurePursuit pp(g::PurePursuitConfig{});  // L_d 2 m
  const g::FrontSteeredPlatform platform{v.wheelbase_m, 35 * std::numbers::pi / 180};
  truth.SetCommand(TimeFromNs(0), 1.0, 0.0);
  double sum_abs = 0, settle_s = -1;
  int n = 0;
  const std::int64_t stop_commands_ns = 120'000'000'000;
  for (std::int64_t t = 0; t <= 150'000'000'000; t += kGridNs) {
    const TruthSample s = truth.Sample(TimeFromNs(t));
    const g::PathProjection f = line.Project(s.p_NB_N_m.head<2>());
    if (settle_s < 0 && std::fabs(f.cross_track_m) < 0.05) settle_s = f.s_m;
    if (settle_s >= 0 && std::fabs(f.cross_track_m) >= 0.05 && t < stop_commands_ns) settle_s = -1;
    if (f.s_m > 40 && t < stop_commands_ns) sum_abs += std::fabs(f.cross_track_m), ++n;
    if (t % 100'000'000 == 0 && t < stop_commands_ns) {  // 10 Hz guidance
      const g::TrackingCommand c = pp.Update(line, PoseOf(s));
      const double k = platform.Reachable(c.curvature_left_per_m);
      ecu.OnFrame(TimeFromNs(t), ToBus(g::EncodeSystemCommand({}, g::IsobusCurvatureFromLeft(k),
                                                              g::kIntendedToSteer)));
    }
    ecu.AdvanceTo(TimeFromNs(t), s.speed_mps);
    truth.SetCommand(TimeFromNs(t + 1), 1.0, -ecu.steer_angle_rad());  // ISOBUS + right → left +
  }
  const double mean_abs = sum_abs / n;
  std::printf("tractor, ISOBUS + ECU, true pose: settled (5 cm) at %.2f m, mean |xte| %.4f m\n",
              settle_s, mean_abs);
  EXPECT_GT(settle_s, 0.0);
  EXPECT_LT(settle_s, 15.0);
  EXPECT_LT(mean_abs, 0.025);  // the ±2.5 cm class, before any position error
  EXPECT_EQ(ecu.counters().watchdog_trips, 1u);
  EXPECT_EQ(ecu.counters().last_watchdog_trip,
            TimeFromNs(stop_commands_ns - 100'000'000 + 300'000'000));
  EXPECT_EQ(ecu.machine_info().exit_reason_code, 5);
  EXPECT_EQ(truth.late_command_restarts(), 0);
}

TEST(ClosedLoopParts, DiffDriveOverTheSerialBaseProtocolStopsOnItsWatchdog) {
  VehicleParams v = VehicleParams::DiffDrive();
  v.yaw_rate_lag_s = 1e-3;  // the wheel motors are the actuators
  v.speed_lag_s = 1e-3;
  v.max_yaw_rate_dps = 1000;
  TruthIntegrator truth(Base(v, 0.3));
  actuator::WheelMotorsConfig mc;
  mc.track_m = v.track_m;
  actuator::WheelMotors motors(mc);
  actuator::BaseSerialSession base(actuator::BaseSerialConfig{}, motors);
  const g::PlannedPath line =
      g::ParsePathText("hil-path 1\nab_line a_m=0,0 b_m=200,0\n", "ab_line");
  g::PurePursuitConfig ppc;
  ppc.lookahead_m = 1.0;
  g::PurePursuit pp(ppc);
  const g::DiffDrivePlatform platform{mc.track_m, mc.wheel_radius_m, mc.max_wheel_speed_radps};
  const std::int64_t stop_commands_ns = 40'000'000'000;
  double x_at_last_command = 0, max_late_xte = 0;
  TruthSample s;
  for (std::int64_t t = 0; t <= 50'000'000'000; t += kGridNs) {
    s = truth.Sample(TimeFromNs(t));
    const g::PathProjection f = line.Project(s.p_NB_N_m.head<2>());
    if (f.s_m > 10 && t < stop_commands_ns)
      max_late_xte = std::max(max_late_xte, std::fabs(f.cross_track_m));
    DeviceOutput replies;
    if (t % 50'000'000 == 0 && t < stop_commands_ns) {  // 20 Hz, move_base's rate
      const g::TrackingCommand c = pp.Update(line, PoseOf(s));
      const g::WheelSpeeds w = platform.FromSpeedAndCurvature(0.5, c.curvature_left_per_m);
      const auto cmd =
          g::FormatMotorSpeeds(g::TicksPerFrame(w.left_radps, mc.encoder_counts_per_rev, 30),
                               g::TicksPerFrame(w.right_radps, mc.encoder_counts_per_rev, 30));
      base.OnHostBytes(TimeFromNs(t), cmd.view(), replies);
      ASSERT_EQ(replies.serial.size(), 1u);
      EXPECT_EQ(replies.serial[0].bytes, "OK\r\n");
      x_at_last_command = s.p_NB_N_m.x();
    }
    motors.AdvanceTo(TimeFromNs(t));
    truth.SetCommand(TimeFromNs(t + 1), motors.body_speed_mps(), motors.body_yaw_rate_radps());
  }
  const double coast_m = s.p_NB_N_m.x() - x_at_last_command;
  std::printf(
      "diff drive, serial base, true pose: max |xte| %.4f m; after the last command the "
      "base went %.2f m and stopped (watchdog at %.3f s)\n",
      max_late_xte, coast_m, ToSeconds(motors.counters().last_watchdog_trip));
  EXPECT_LT(max_late_xte, 0.02);
  EXPECT_TRUE(motors.stopped_by_watchdog());
  EXPECT_EQ(motors.counters().last_watchdog_trip,
            TimeFromNs(stop_commands_ns - 50'000'000 + 2'000'000'000));
  EXPECT_NEAR(s.speed_mps, 0.0, 1e-6);
  // 2 s at 0.5 m/s until the watchdog, then the deceleration through the motors' limits.
  EXPECT_GT(coast_m, 1.0);
  EXPECT_LT(coast_m, 1.2);
}

}  // namespace
}  // namespace hil::truth

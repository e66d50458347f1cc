// The truth with commands as inputs (closed loop): piecewise-constant commands on the command
// grid without restarts, the analytic steady turn, determinism whatever the
// sampling, and late commands honoured by a replay.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "hil/truth/truth_integrator.h"

namespace hil::truth {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

TruthConfig ClosedLoop() {
  TruthConfig c;
  c.origin = {35.4796096, 50.5979765, 1300};
  c.vehicle = VehicleParams::Tractor();
  c.heading_deg = 90;  // east
  c.external_commands = true;
  c.command_period_s = 0.01;
  c.earth_rotation = false;
  return c;
}

Time Sec(double s) { return TimeFromSeconds(s); }

TEST(TruthCommands, FollowsPiecewiseConstantCommands) {
  TruthIntegrator truth(ClosedLoop());
  truth.SetCommand(Sec(0), 1.0, 0.0);
  const TruthSample a = truth.Sample(Sec(20));
  EXPECT_NEAR(a.p_NB_N_m.x(), 20.0, 1e-6);  // started at speed, straight east
  EXPECT_NEAR(a.p_NB_N_m.y(), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(a.speed_cmd_mps, 1.0);
  const double delta = 10 * kDeg;
  truth.SetCommand(Sec(20.005), 1.0, delta);  // acts at the grid instant 20.01 s
  const TruthSample b = truth.Sample(Sec(20.009));
  EXPECT_DOUBLE_EQ(b.steer_cmd_rad, 0.0);
  const TruthSample c = truth.Sample(Sec(20.01));
  EXPECT_DOUBLE_EQ(c.steer_cmd_rad, delta);
  const TruthSample d = truth.Sample(Sec(40));  // steady turn: ψ̇ = v tan δ / L
  EXPECT_NEAR(d.steer_rad, delta, 1e-9);
  EXPECT_NEAR(d.w_NB_B_radps.z(), std::tan(delta) / truth.config().vehicle.wheelbase_m, 1e-7);
  EXPECT_EQ(truth.late_command_restarts(), 0);
}

// 10 Hz: sample at the tick, the command arrives 1 ms later (acts at the next grid instant); the
// steering changes at ticks 1, 5, 10, …, 100.
TruthSample SteerSequence(TruthIntegrator& truth) {
  truth.SetCommand(Sec(0), 1.0, 0.0);
  for (int k = 1; k <= 100; ++k) {
    truth.Sample(Sec(0.1 * k));
    const double delta = (k / 5) % 2 ? 5 * kDeg : -5 * kDeg;
    truth.SetCommand(Sec(0.1 * k + 0.001), 1.0, delta);
  }
  return truth.Sample(Sec(10.05));
}

// A new command changes only the lags' targets: v and u do not jump, so e, n and ψ keep a
// continuous right-hand side and CVODE goes on without a restart (its error control takes the
// kink); the path agrees with a run at a thousandfold tighter tolerance.
TEST(TruthCommands, ACommandChangeNeedsNoRestart) {
  TruthIntegrator truth(ClosedLoop());
  const TruthSample end = SteerSequence(truth);
  EXPECT_EQ(truth.commands(), 101);
  EXPECT_EQ(truth.reinits(), 0);
  EXPECT_EQ(truth.late_command_restarts(), 0);
  TruthConfig tight = ClosedLoop();
  tight.rtol = 1e-13;
  tight.atol_m = 1e-12;
  TruthIntegrator reference(tight);
  const TruthSample ref = SteerSequence(reference);
  EXPECT_GT(std::abs(end.p_NB_N_m.y()), 0.01) << "the steering moved the vehicle";
  EXPECT_NEAR(end.p_NB_N_m.x(), ref.p_NB_N_m.x(), 1e-6);
  EXPECT_NEAR(end.p_NB_N_m.y(), ref.p_NB_N_m.y(), 1e-6);
  EXPECT_NEAR(end.steer_rad, ref.steer_rad, 1e-9);
}

std::vector<TruthSample> RunWithSampling(double sample_period_s) {
  TruthIntegrator truth(ClosedLoop());
  truth.SetCommand(Sec(0), 0.8, 0.0);
  std::vector<TruthSample> at_ticks;
  for (int k = 1; k <= 200; ++k) {
    const double t = 0.1 * k;
    for (double s = t - 0.1 + sample_period_s; s < t - 1e-12; s += sample_period_s)
      truth.Sample(Sec(s));
    at_ticks.push_back(truth.Sample(Sec(t)));
    truth.SetCommand(Sec(t + 0.001), 0.8, 0.2 * std::sin(0.3 * t));
  }
  return at_ticks;
}

TEST(TruthCommands, SamplesDoNotDependOnTheSamplingSchedule) {
  const std::vector<TruthSample> coarse = RunWithSampling(0.1), fine = RunWithSampling(0.007);
  ASSERT_EQ(coarse.size(), fine.size());
  for (std::size_t i = 0; i < coarse.size(); ++i) {
    EXPECT_EQ(coarse[i].p_NB_N_m, fine[i].p_NB_N_m) << i;
    EXPECT_EQ(coarse[i].q_NB.coeffs(), fine[i].q_NB.coeffs()) << i;
  }
}

TEST(TruthCommands, ALateCommandIsHonouredByAReplay) {
  TruthIntegrator on_time(ClosedLoop()), late(ClosedLoop());
  on_time.SetCommand(Sec(0), 1.0, 0.0);
  late.SetCommand(Sec(0), 1.0, 0.0);
  on_time.Sample(Sec(5));
  on_time.SetCommand(Sec(5.001), 1.0, 3 * kDeg);
  late.Sample(Sec(7));  // already past 5 s
  late.SetCommand(Sec(5.001), 1.0, 3 * kDeg);
  EXPECT_EQ(late.late_command_restarts(), 1);
  const TruthSample a = on_time.Sample(Sec(12)), b = late.Sample(Sec(12));
  EXPECT_EQ(a.p_NB_N_m, b.p_NB_N_m);
  EXPECT_THROW(late.SetCommand(Sec(4), 1.0, 0.0), std::invalid_argument);
  TruthConfig open = ClosedLoop();
  open.external_commands = false;
  TruthIntegrator open_loop(open);
  EXPECT_THROW(open_loop.SetCommand(Sec(1), 1.0, 0.0), std::logic_error);
}

TEST(TruthCommands, DiffDriveTakesYawRate) {
  TruthConfig c = ClosedLoop();
  c.vehicle = VehicleParams::DiffDrive();
  TruthIntegrator truth(c);
  truth.SetCommand(Sec(0), 0.5, 0.1);
  const TruthSample s = truth.Sample(Sec(30));
  EXPECT_NEAR(s.w_NB_B_radps.z(), 0.1, 1e-7);
  EXPECT_NEAR(s.speed_mps, 0.5, 1e-9);
}

// The closed loop's first-order hold (command_hold_s): an actuator slowing at 3 m/s², sampled
// every 10 ms, gives the truth a speed that ramps between its samples, so the acceleration the
// IMU reads is the actuator's at every instant, just after a command too (a step through a 1 ms
// lag read 30 m/s² there), and the speed lost is the actuator's.
TEST(TruthCommands, TheHoldGivesTheActuatorsAccelerationAtEveryInstant) {
  TruthConfig c = ClosedLoop();
  c.command_hold_s = c.command_period_s;
  TruthIntegrator truth(c);
  truth.SetCommand(Sec(0), 0.5, 0.0);
  truth.Sample(Sec(1.0));
  double v = 0.5;
  for (int k = 1; k <= 17; ++k) {  // 0.5 m/s to 0 at 0.03 m/s per 10 ms tick
    v = std::max(0.0, v - 0.03);
    truth.SetCommand(Sec(1.0 + 0.01 * k), v, 0.0);
  }
  for (const double t : {1.0101, 1.0105, 1.0199, 1.0801, 1.15}) {
    const TruthSample s = truth.Sample(Sec(t));
    EXPECT_NEAR(s.a_NB_N_mps2.x(), -3.0, 1e-6) << "t " << t;
  }
  const TruthSample rest = truth.Sample(Sec(1.3));
  EXPECT_NEAR(rest.speed_mps, 0.0, 1e-12);
  EXPECT_NEAR(rest.a_NB_N_mps2.x(), 0.0, 1e-9);
  EXPECT_EQ(truth.late_command_restarts(), 0);
}

}  // namespace
}  // namespace hil::truth

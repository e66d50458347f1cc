// Pure pursuit and Stanley in closed loop on kinematic models (a rear-axle bicycle with an optional
// steering lag, and a differential-drive unicycle): settling after a 1 m offset, steady-state
// cross-track on a straight line and a circle, a boustrophedon and a rectangle driven to the end,
// and no allocation in the control loop.
#include "hil/estimator/guidance/path_tracker.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/guidance/path_file.h"

// Counts every allocation of this test executable (to show the control loop makes none).
static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace hil::estimator::guidance {
namespace {

constexpr double kControlPeriod_s = 0.1;  // 10 Hz, the ISOBUS command rate
constexpr int kPlantSubsteps = 10;

// Rear-axle bicycle: κ = tan δ / L, δ follows the command with a first-order lag τ (0: none).
struct Bicycle {
  VehiclePose2d pose;
  double wheelbase_m = 2.5;
  double steer_rad = 0;
  double steer_tau_s = 0;
  void Step(double steer_cmd_rad, double dt) {
    steer_rad = steer_tau_s > 0
                    ? steer_cmd_rad + (steer_rad - steer_cmd_rad) * std::exp(-dt / steer_tau_s)
                    : steer_cmd_rad;
    Arc(std::tan(steer_rad) / wheelbase_m, dt);
  }
  // Exact motion on an arc of curvature k for dt.
  void Arc(double k, double dt) {
    const double ds = pose.speed_mps * dt;
    const double dyaw = k * ds;
    const double chord_yaw = pose.yaw_rad + 0.5 * dyaw;
    const double chord = std::fabs(dyaw) < 1e-9 ? ds : 2.0 * std::sin(0.5 * dyaw) / k;
    pose.p_EN_m += chord * Eigen::Vector2d(std::cos(chord_yaw), std::sin(chord_yaw));
    pose.yaw_rad += dyaw;
  }
};

struct Trace {
  std::vector<double> s_m, xte_m;
  bool ended = false;
  double SettlingDistance(double band_m) const {  // arc length after which |xte| stays in band
    for (std::size_t i = s_m.size(); i-- > 0;)
      if (std::fabs(xte_m[i]) > band_m) return i + 1 < s_m.size() ? s_m[i + 1] - s_m[0] : 1e9;
    return 0.0;
  }
  double MaxAbsBetween(double s0, double s1) const {
    double m = 0;
    for (std::size_t i = 0; i < s_m.size(); ++i)
      if (s_m[i] >= s0 && s_m[i] <= s1) m = std::max(m, std::fabs(xte_m[i]));
    return m;
  }
};

template <typename Controller>
Trace RunBicycle(Controller& ctl, const PlannedPath& path, Bicycle car, double seconds,
                 const FrontSteeredPlatform& platform) {
  Trace tr;
  for (double t = 0; t < seconds; t += kControlPeriod_s) {
    const TrackingCommand c = ctl.Update(path, car.pose);
    tr.s_m.push_back(c.s_m);
    tr.xte_m.push_back(c.cross_track_m);
    if (c.end_of_path) {
      tr.ended = true;
      break;
    }
    const double steer = platform.SteerAngleFromCurvature(c.curvature_left_per_m);
    for (int k = 0; k < kPlantSubsteps; ++k) car.Step(steer, kControlPeriod_s / kPlantSubsteps);
  }
  return tr;
}

PlannedPath Straight() { return ParsePathText("hil-path 1\nab_line a_m=0,0 b_m=300,0\n", "ab"); }
PlannedPath Circle20() {
  return ParsePathText("hil-path 1\ncircle center_m=0,0 radius_m=20 laps=2 step_m=0.05\n", "c");
}

Bicycle Tractor(const Eigen::Vector2d& p, double yaw, double tau_s) {
  Bicycle b;
  b.pose.p_EN_m = p;
  b.pose.yaw_rad = yaw;
  b.pose.speed_mps = 1.0;
  b.steer_tau_s = tau_s;
  return b;
}

const FrontSteeredPlatform kTractor{2.5, 0.6};

TEST(PurePursuit, SettlesAfterA1mOffsetAndHoldsAStraightLine) {
  PurePursuit pp(PurePursuitConfig{});  // L_d = 2 m, paper 003's baseline
  const Trace tr = RunBicycle(pp, Straight(), Tractor({0, -1}, 0, 0), 260, kTractor);
  const double settle = tr.SettlingDistance(0.05);
  double overshoot = 0;  // the start is 1 m right (negative): overshoot is on the left
  for (double e : tr.xte_m) overshoot = std::max(overshoot, e);
  std::printf("pure pursuit, L_d 2 m, 1 m step: settling (5 cm) after %.2f m, overshoot %.3f m\n",
              settle, overshoot);
  EXPECT_LT(overshoot, 0.15);  // ζ = 0.707: 4 % of the step in the linear model
  // Linearised: e'' + (2v/L_d) e' + (2v²/L_d²) e = 0, ζ = 0.707, ω_n = 0.707 rad/s: 5 cm of 1 m
  // within ≈ 3/(ζ ω_n) = 6 s = 6 m; allow for the non-linear start and the 10 Hz sampling.
  EXPECT_LT(settle, 10.0);
  EXPECT_GT(settle, 2.0);
  EXPECT_LT(tr.MaxAbsBetween(100, 250), 1e-4);
}

TEST(PurePursuit, TracksACircleWithinTheChordError) {
  PurePursuit pp(PurePursuitConfig{});
  const Trace tr =
      RunBicycle(pp, Circle20(), Tractor({20, 0}, std::numbers::pi / 2, 0), 200, kTractor);
  const double steady = tr.MaxAbsBetween(60, 190);
  std::printf("pure pursuit on R 20 m: steady-state max |xte| %.2e m\n", steady);
  EXPECT_LT(steady, 2e-3);
}

// In the steady turn the steering angle is constant, so a lag does not change where it settles.
TEST(PurePursuit, SteeringLagDoesNotMoveTheSteadyStateOnACircle) {
  PurePursuit pp(PurePursuitConfig{});
  const Trace tr =
      RunBicycle(pp, Circle20(), Tractor({20, 0}, std::numbers::pi / 2, 0.3), 200, kTractor);
  const double steady = tr.MaxAbsBetween(60, 190);
  std::printf("pure pursuit on R 20 m, steering lag 0.3 s: steady-state max |xte| %.2e m\n",
              steady);
  EXPECT_LT(steady, 2e-3);
}

TEST(Stanley, SettlesAfterA1mOffsetAndHoldsLineAndCircle) {
  Stanley st(StanleyConfig{});
  const Trace line = RunBicycle(st, Straight(), Tractor({0, -1}, 0, 0), 260, kTractor);
  const double settle = line.SettlingDistance(0.05);
  std::printf("stanley, k 2.5, 1 m step: settling (5 cm) after %.2f m\n", settle);
  EXPECT_LT(settle, 10.0);
  EXPECT_LT(line.MaxAbsBetween(100, 250), 1e-4);
  Stanley st2(StanleyConfig{});
  const Trace circle =
      RunBicycle(st2, Circle20(), Tractor({20, 0}, std::numbers::pi / 2, 0), 200, kTractor);
  // Stanley regulates the front axle onto the path; the rear axle runs inside the circle by
  // R − √(R² − L²).
  const double rear_inside = 20.0 - std::sqrt(400.0 - 2.5 * 2.5);
  EXPECT_NEAR(circle.MaxAbsBetween(60, 190), rear_inside, 0.01);
}

// Unicycle driven by wheel speeds (differential drive).
Trace RunDiffDrive(PurePursuit& ctl, const PlannedPath& path, VehiclePose2d pose, double seconds,
                   const DiffDrivePlatform& base, double speed_mps) {
  Trace tr;
  Bicycle body;  // used for its exact arc motion only
  body.pose = pose;
  for (double t = 0; t < seconds; t += kControlPeriod_s) {
    const TrackingCommand c = ctl.Update(path, body.pose);
    tr.s_m.push_back(c.s_m);
    tr.xte_m.push_back(c.cross_track_m);
    if (c.end_of_path) {
      tr.ended = true;
      break;
    }
    const WheelSpeeds w = base.FromSpeedAndCurvature(speed_mps, c.curvature_left_per_m);
    const double v = 0.5 * (w.left_radps + w.right_radps) * base.wheel_radius_m;
    const double yaw_rate = (w.right_radps - w.left_radps) * base.wheel_radius_m / base.track_m;
    body.pose.speed_mps = v;
    body.Arc(std::fabs(v) > 1e-9 ? yaw_rate / v : 0.0, kControlPeriod_s);
  }
  return tr;
}

TEST(PurePursuit, DrivesADifferentialDriveBaseRoundARectangle) {
  const PlannedPath rect = ParsePathText(
      "hil-path 1\nrectangle corner_m=0,0 length_m=20 width_m=8 heading_deg=90 turn=left "
      "corner_radius_m=1.5\n",
      "rect");
  PurePursuitConfig cfg;
  cfg.lookahead_m = 1.0;
  PurePursuit pp(cfg);
  VehiclePose2d start;
  start.p_EN_m = {4, 0.5};  // on the first side (which starts 1.5 m from the corner)
  const Trace tr = RunDiffDrive(pp, rect, start, 400, DiffDrivePlatform{}, 0.5);
  EXPECT_TRUE(tr.ended);
  EXPECT_LT(tr.MaxAbsBetween(8, 14), 0.01);  // the first side, after the 0.5 m offset
  const double settled = tr.MaxAbsBetween(8, rect.length_m());
  std::printf("diff drive round a 20 x 8 m rectangle: max |xte| %.3f m after settling (turns)\n",
              settled);
  EXPECT_LT(settled, 0.2);
}

TEST(PurePursuit, DrivesABoustrophedonToItsEnd) {
  const PlannedPath field = ParsePathText(
      "hil-path 1\nboustrophedon start_m=0,0 heading_deg=0 row_length_m=60 row_spacing_m=6 "
      "rows=4 turn_radius_m=3\n",
      "field");
  PurePursuit pp(PurePursuitConfig{});
  const Trace tr =
      RunBicycle(pp, field, Tractor({0, 0}, std::numbers::pi / 2, 0.15), 600, kTractor);
  EXPECT_TRUE(tr.ended);
  // On each row, 15 m after the turn, the tractor is back on the line.
  for (int row = 1; row < 4; ++row) {
    const double row_start = row * (60 + 3 * std::numbers::pi);
    EXPECT_LT(tr.MaxAbsBetween(row_start + 15, row_start + 58), 0.02) << "row " << row;
  }
}

TEST(PathTracker, TheControlLoopDoesNotAllocate) {
  const PlannedPath field = ParsePathText(
      "hil-path 1\nboustrophedon start_m=0,0 heading_deg=0 row_length_m=60 row_spacing_m=6 "
      "rows=4 turn_radius_m=3\n",
      "field");
  PurePursuit pp(PurePursuitConfig{});
  Stanley st(StanleyConfig{});
  Bicycle car = Tractor({0.3, 0}, std::numbers::pi / 2, 0);
  const long before = g_allocations.load();
  double sink = 0;
  for (int i = 0; i < 2000; ++i) {
    const TrackingCommand a = pp.Update(field, car.pose);
    const TrackingCommand b = st.Update(field, car.pose);
    sink += b.curvature_left_per_m;
    car.Step(kTractor.SteerAngleFromCurvature(a.curvature_left_per_m), kControlPeriod_s);
  }
  EXPECT_EQ(g_allocations.load(), before);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(Platforms, CurvatureMapsOntoSteerAngleAndWheelSpeeds) {
  EXPECT_NEAR(kTractor.SteerAngleFromCurvature(0.1), std::atan(0.25), 1e-15);
  EXPECT_EQ(kTractor.SteerAngleFromCurvature(10.0), 0.6);
  EXPECT_NEAR(kTractor.Reachable(10.0), std::tan(0.6) / 2.5, 1e-15);
  const DiffDrivePlatform base{0.5, 0.1, 20.0};
  const WheelSpeeds w = base.FromSpeedAndCurvature(1.0, 1.0);  // ω = 1 rad/s
  EXPECT_NEAR(w.left_radps, 7.5, 1e-12);
  EXPECT_NEAR(w.right_radps, 12.5, 1e-12);
  const WheelSpeeds fast = base.FromSpeedAndCurvature(4.0, 1.0);  // 50 rad/s wanted: scaled
  EXPECT_NEAR(fast.right_radps, 20.0, 1e-12);
  EXPECT_NEAR(fast.left_radps / fast.right_radps, 0.6, 1e-12);
}

}  // namespace
}  // namespace hil::estimator::guidance

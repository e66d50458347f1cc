// The INS's velocity ripple at the fix instants (FixVelocityRipple, issue 39, paper 000's rig): a
// board point-sampled at 10 Hz on a 23 Hz engine aliases it to 3 Hz, the INS integrates that into
// a velocity ripple, and 1 Hz fixes see the ripple at the same phase every time. The IMU and the
// fixes are generated here with a seeded noise.
#include "hil/estimator/fix_velocity_ripple.h"

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "hil/estimator/navigator.h"

#include "paper000_robot_params.h"

namespace hil::estimator {
namespace {

using namespace std::chrono_literals;

constexpr double kPi = std::numbers::pi;

// the ripple FixVelocityRipple finds after one interval of n samples of dt whose specific force
// (navigation frame, x only) is a(t)
template <typename F>
double RippleAfter(int n, double dt, F a, double t0_s = 0) {
  FixVelocityRipple r;
  for (int k = 1; k <= n; ++k) r.Add(Eigen::Vector3d(a(t0_s + k * dt) * dt, 0, 0), dt);
  return r.Ripple_N_mps(1.5).x();
}

TEST(FixVelocityRippleTest, FindsAStroboscopicRippleAndLeavesLinearMotion) {
  // GIVEN a 23 Hz vibration of 0.4 m/s² point-sampled at 10 Hz (a 3 Hz alias), 1 s intervals
  const auto vib = [](double t) { return 0.4 * std::sin(2 * kPi * 23.0 * t + 0.7); };
  // the INS's velocity ripple at the interval's end: the running sum less its mean over a period
  double v = 0, sum = 0;
  std::vector<double> u;
  for (int k = 1; k <= 10; ++k) u.push_back(v += vib(k * 0.1) * 0.1);
  for (int k = 0; k < 10; ++k) sum += 0.5 * ((k ? u[k - 1] : 0.0) + u[k]) * 0.1;
  const double ripple_end = u.back() - sum;  // u(T) is ~0 after three whole periods
  // THEN the estimate is the ripple at the fix instant, centimetres per second here
  EXPECT_GT(std::abs(ripple_end), 0.001);
  EXPECT_NEAR(RippleAfter(10, 0.1, vib), ripple_end, 1e-12);
  // AND a constant acceleration (the vehicle's, or the INS's slow drift) leaves nothing
  EXPECT_NEAR(RippleAfter(10, 0.1, [](double) { return 0.05; }), 0.0, 1e-12);
  // AND an interval longer than the limit (a gap) leaves nothing
  EXPECT_EQ(RippleAfter(20, 0.1, vib), 0.0);
  FixVelocityRipple none;
  EXPECT_EQ(none.Ripple_N_mps(1.5), Eigen::Vector3d::Zero());
}

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
const Lla kOrigin{35.48, 50.60, 1312.0};
constexpr double kSpeed_mps = 0.44;

NavigatorParams Params(bool ripple) {
  NavigatorParams p = test::Paper000RobotParams();
  p.gnss_vel_noise.enabled = false;
  p.fix_velocity_ripple = ripple;
  return p;
}

// A level vehicle heading north at 0.44 m/s; IMU at 10 Hz with the 23 Hz vibration along the body
// x axis point-sampled; fixes at 1 Hz (position error correlated, velocity 3 cm/s white). Returns
// the mean north velocity error over the last 60 s at the IMU epochs (whole ripple periods: the
// ripple itself averages out, what stays is the bias the fixes read into the velocity).
double MeanVelocityError(bool ripple, double vibration_mps2, unsigned seed = 39) {
  Navigator nav(Params(ripple));
  const LocalTangentFrame frame{kOrigin};
  const Eigen::Quaterniond q_NB(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d v_N(0, kSpeed_mps, 0);
  nav.InitializeAt(kT0, kOrigin, v_N, q_NB);
  const Eigen::Matrix3d C = q_NB.toRotationMatrix();
  const Eigen::Vector3d g_N(0, 0, -NormalGravity(kOrigin.lat_deg, kOrigin.height_m));
  const Eigen::Vector3d w_ie = frame.w_IE_N();
  const Eigen::Vector3d f_B = C.transpose() * (2.0 * w_ie.cross(v_N) - g_N);
  const Eigen::Vector3d w_B = C.transpose() * w_ie;
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double dt = 0.1, phi = std::exp(-1.0 / 4.5);
  Eigen::Vector3d err_N_m = Eigen::Vector3d::Zero();
  double sum = 0;
  int n = 0;
  for (int k = 1; k <= 1800; ++k) {
    const double t = k * dt;
    ImuSample s;
    s.t = kT0 + Nanoseconds{std::llround(t * 1e9)};
    s.dt_s = dt;
    s.delta_velocity_B_mps =
        (f_B + Eigen::Vector3d(vibration_mps2 * std::sin(2 * kPi * 23.0 * t), 0, 0)) * dt;
    for (int i = 0; i < 3; ++i) s.delta_velocity_B_mps[i] += 0.0125 * std::sqrt(dt) * n01(rng);
    s.delta_angle_B_rad = w_B * dt;
    if (k % 10 == 0) {
      for (int i = 0; i < 2; ++i)
        err_N_m[i] = phi * err_N_m[i] + std::sqrt(1 - phi * phi) * 0.25 * n01(rng);
      GnssSample g;
      g.t = s.t;
      g.position = frame.ToLla(v_N * t + err_N_m);
      g.pos_std_enu_m = {0.03, 0.03, 0.06};
      g.hdop = 1.0;
      g.has_velocity = true;
      g.vel_enu_mps = Eigen::Vector3d(0.03 * n01(rng), kSpeed_mps + 0.03 * n01(rng), 0);
      g.vel_std_enu_mps = {0.03, 0.03, 0.06};
      nav.Push(g);
    }
    nav.Push(s);
    nav.Update();
    if (t > 120) {
      sum += nav.Output().v_N_mps.y() - kSpeed_mps;
      ++n;
    }
  }
  return sum / n;
}

TEST(FixVelocityRippleTest, NavigatorKeepsTheRippleOutOfItsVelocity) {
  // GIVEN the same run without vibration (its velocity bias comes from the fixes' noise)
  const double no_vibration = MeanVelocityError(false, 0.0);
  // WHEN the board vibrates (a 2 cm/s ripple at 3 Hz: the fixes see it at one phase for minutes)
  // THEN with the ripple left out of the fix velocity's innovation the velocity is as without
  const double with = MeanVelocityError(true, 0.4);
  EXPECT_NEAR(with, no_vibration, 0.001);
  // (the old comparison, the ripple kept in: the fixes read it as a velocity error that stays)
  const double without = MeanVelocityError(false, 0.4);
  EXPECT_GT(std::abs(without - no_vibration), 0.01);
}

}  // namespace
}  // namespace hil::estimator

// The accelerometer's white-noise density from its own sample scatter (AccelScatter, issue 39):
// white noise reads as its density, an engine's vibration aliased by point sampling reads as the
// far larger noise it is to the INS; an IMU read out fast enough to measure its vibration is not
// judged by its scatter.
#include "hil/estimator/accel_scatter.h"

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "hil/estimator/navigator.h"

namespace hil::estimator {
namespace {

// density (m/s²/√Hz) AccelScatter finds in n samples of f(k) at dt
template <typename F>
double Density(double dt, int n, F f) {
  AccelScatter s(10.0);
  for (int k = 0; k < n; ++k) s.Add(f(k) * dt, dt);
  return std::sqrt(s.density2_m2ps3());
}

TEST(AccelScatterTest, WhiteNoiseReadsAsItsDensity) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double dt = 0.1, q = 0.02;  // 0.02 m/s²/√Hz at 10 Hz: σ = q / √dt per sample
  const double d = Density(dt, 20000, [&](int) -> Eigen::Vector3d {
    return Eigen::Vector3d(n01(rng), n01(rng), n01(rng)) * q / std::sqrt(dt) +
           Eigen::Vector3d(0, 0, 9.81);
  });
  EXPECT_NEAR(d, q, 0.15 * q);
}

TEST(AccelScatterTest, AliasedVibrationIsNoiseSlowStepsAreNot) {
  // a 23 Hz vibration of 1.2 m/s² on the up axis, point-sampled at 10 Hz (paper 000's Razor)
  const double aliased = Density(0.1, 3000, [](int k) -> Eigen::Vector3d {
    return Eigen::Vector3d(0, 0,
                           9.81 + 1.2 * std::sin(2 * std::numbers::pi * 23.0 * 0.1 * k + 0.3));
  });
  EXPECT_GT(aliased, 0.15);  // against a Razor data sheet's 0.0125 m/s²/√Hz
  // a walker's 2 Hz steps of 3 m/s² (and its foot's impacts) read at 200 Hz: measured, not
  // aliased; an IMU that fast is not judged by its scatter
  const double steps = Density(0.005, 20000, [](int k) -> Eigen::Vector3d {
    return Eigen::Vector3d(3.0 * std::sin(2 * std::numbers::pi * 2.0 * 0.005 * k),
                           (k % 100 == 0) ? 20.0 : 0.0, 9.81);
  });
  EXPECT_EQ(steps, 0.0);
  // nothing before the warm-up
  AccelScatter s(10.0);
  s.Add(Eigen::Vector3d(1, 2, 3), 0.1);
  EXPECT_EQ(s.density2_m2ps3(), 0.0);
}

// the navigator floors its EKF's accelerometer noise there: a vibrating 10 Hz board, not a 100 Hz
// one
double NavigatorFloor(double dt_s) {
  NavigatorParams p;
  p.mode = NavMode::kEkf;
  p.fusion_horizon = Nanoseconds{0};
  Navigator nav(p);
  const GpsTime t0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
  nav.InitializeAt(t0, Lla{35.48, 50.60, 1312.0}, Eigen::Vector3d::Zero(),
                   Eigen::Quaterniond::Identity());
  for (int k = 1; k <= static_cast<int>(60.0 / dt_s); ++k) {
    ImuSample s;
    s.t = t0 + Nanoseconds{std::llround(k * dt_s * 1e9)};
    s.dt_s = dt_s;
    s.delta_velocity_B_mps =
        Eigen::Vector3d(0, 0, 9.79 + 1.2 * std::sin(2 * std::numbers::pi * 23.0 * k * dt_s)) * dt_s;
    nav.Push(s);
    nav.Update();
  }
  return nav.ekf().accel_noise_floor();
}

TEST(AccelScatterTest, NavigatorFloorsTheAccelerometerNoise) {
  EXPECT_GT(NavigatorFloor(0.1), 0.15 * 0.15);
  EXPECT_EQ(NavigatorFloor(0.01), 0.0);
}

// the velocity covariance (ENU) after one 0.1 s step of a board rolled 90° (its z axis level,
// pointing west) and yawed 0.5 rad, with the given floor per body axis
Eigen::Matrix3d VelocityCovarianceAfterStep(const Eigen::Vector3d& floor_B_m2ps3) {
  EarthModel earth;
  earth.g_N_mps2 = Eigen::Vector3d(0, 0, -9.81);
  EkfParams p;
  p.accel_noise_mps2_rthz = 0.0125;
  ErrorStateEkf ekf(p, earth);
  NavState s;
  s.q_NB = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) *
           Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX());
  ekf.Initialize(s);
  ekf.SetAccelNoiseFloor(floor_B_m2ps3);
  ekf.Predict(Eigen::Vector3d::Zero(), s.q_NB.conjugate() * Eigen::Vector3d(0, 0, 9.81) * 0.1, 0.1);
  return ekf.covariance().block<3, 3>(ekf_index::kVel, ekf_index::kVel);
}

TEST(AccelScatterTest, FloorHoldsPerBodyAxis) {
  // GIVEN a floor on the board's z axis only (an engine's vibration along it), 0.09 m²/s³
  const Eigen::Matrix3d added = VelocityCovarianceAfterStep(Eigen::Vector3d(0, 0, 0.09)) -
                                VelocityCovarianceAfterStep(Eigen::Vector3d::Zero());
  // THEN the velocity gains it along the board's z axis as it lies in ENU, and only there (an
  // isotropic floor gave every direction the largest axis's: the z vibration flooded the
  // horizontal INS of paper 000's Razor, 0.3 m/s²/√Hz for its 0.1 along x)
  const Eigen::Quaterniond q_NB = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX());
  const Eigen::Vector3d z_N = q_NB * Eigen::Vector3d::UnitZ();
  const double expected = (0.09 - 0.0125 * 0.0125) * 0.1;
  EXPECT_NEAR(z_N.dot(added * z_N), expected, 1e-9);
  EXPECT_NEAR(added.trace(), expected, 1e-9);
  EXPECT_NEAR(added(2, 2), 0.0, 1e-9);  // the vertical is the board's y axis here: no floor
}

}  // namespace
}  // namespace hil::estimator

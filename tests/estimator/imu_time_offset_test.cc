// The IMU tag lag estimate (imu_time_offset.h): a car in S-turns at 6 m/s, its IMU's heading
// increments tagged late, its GNSS courses at 10 Hz from a noisy velocity; the antenna ahead of
// the body. Generated here with a seeded noise.
#include "hil/estimator/imu_time_offset.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
constexpr double kSpeed = 6.0;

// yaw rate: 5 s straight, 1 s ramp to ±0.5 rad/s, 3 s turn, 1 s ramp down; the sign alternates
double YawRate(double t, bool turns) {
  if (!turns) return 0.0;
  const double period = 10.0;
  const double u = std::fmod(t, period);
  const double sign = static_cast<long>(t / period) % 2 == 0 ? 1.0 : -1.0;
  double w = 0.0;
  if (u < 5.0) {
    w = 0.0;
  } else if (u < 6.0) {
    w = 0.5 * (u - 5.0);
  } else if (u < 9.0) {
    w = 0.5;
  } else {
    w = 0.5 * (10.0 - u);
  }
  return sign * w;
}

struct Drive {
  double lag_s = 0.1;
  bool turns = true;
  double lever_x_m = 1.0;
  double vel_std_mps = 0.05;
  double gyro_std_radps = 0.005;  // per 100 Hz sample: a rough consumer MEMS on a running engine

  ImuTimeOffset Run(double duration_s, bool tell_lever_arm = true) {
    ImuTimeOffset est;
    if (tell_lever_arm) est.SetLeverArm(lever_x_m, 0.0);
    std::mt19937 rng(41);
    std::normal_distribution<double> n01(0.0, 1.0);
    const double dt = 0.001;  // the truth's integration step
    double psi = 0.3;
    double last_imu_psi = psi;
    for (int k = 1; k * dt <= duration_s + 1e-9; ++k) {
      const double t = k * dt;
      psi += YawRate(t - 0.5 * dt, turns) * dt;
      if (k % 10 == 0) {  // an IMU sample sensed at t, tagged lag_s later
        const double inc = psi - last_imu_psi + gyro_std_radps * 0.01 * n01(rng);
        last_imu_psi = psi;
        est.AddImu(kT0 + Nanoseconds{std::llround((t + lag_s) * 1e9)}, inc);
      }
      if (k % 100 == 0) {  // a fix at t: the antenna's velocity (ahead of the body by lever_x)
        const double w = YawRate(t, turns);
        const double chi = psi + std::atan2(w * lever_x_m, kSpeed);
        const double v = std::hypot(kSpeed, w * lever_x_m);
        est.AddVelocity(kT0 + Nanoseconds{std::llround(t * 1e9)},
                        v * std::cos(chi) + vel_std_mps * n01(rng),
                        v * std::sin(chi) + vel_std_mps * n01(rng), vel_std_mps);
      }
    }
    return est;
  }
};

TEST(ImuTimeOffsetTest, FindsTheLagOfATurningCar) {
  Drive d;
  const ImuTimeOffset est = d.Run(120.0);
  ASSERT_TRUE(est.lag_s().has_value())
      << "best " << est.best_lag_s() << " σ " << est.lag_std_s() << " evidence " << est.evidence();
  EXPECT_NEAR(*est.lag_s(), 0.1, 0.005);
  EXPECT_LT(est.lag_std_s(), 0.01);
  RecordProperty("lag_s", std::to_string(*est.lag_s()));
}

TEST(ImuTimeOffsetTest, FindsAnImuTaggedEarly) {
  Drive d;
  d.lag_s = -0.04;
  const ImuTimeOffset est = d.Run(120.0);
  ASSERT_TRUE(est.lag_s().has_value());
  EXPECT_NEAR(*est.lag_s(), -0.04, 0.005);
}

TEST(ImuTimeOffsetTest, NoLagIsNoLag) {
  Drive d;
  d.lag_s = 0.0;
  const ImuTimeOffset est = d.Run(300.0);
  EXPECT_FALSE(est.lag_s().has_value()) << est.best_lag_s();
  EXPECT_NEAR(est.best_lag_s(), 0.0, 0.01);
}

// an antenna 1 m ahead of the body turns its course ω l / v (0.17 s at 6 m/s) ahead of the
// heading: without the lever arm that reads as an IMU tagged that much late
TEST(ImuTimeOffsetTest, TheLeverArmIsNotALag) {
  Drive d;
  d.lag_s = 0.0;
  const ImuTimeOffset told = d.Run(120.0, true);
  const ImuTimeOffset not_told = d.Run(120.0, false);
  EXPECT_FALSE(told.lag_s().has_value());
  ASSERT_TRUE(not_told.lag_s().has_value());
  EXPECT_GT(*not_told.lag_s(), 0.1);
}

TEST(ImuTimeOffsetTest, StraightDrivingGivesNoEvidence) {
  Drive d;
  d.turns = false;
  const ImuTimeOffset est = d.Run(300.0);
  EXPECT_FALSE(est.lag_s().has_value());
  EXPECT_LT(est.evidence(), ImuTimeOffsetParams{}.evidence);
}

}  // namespace
}  // namespace hil::estimator

// VibrationVelocity (vibration_velocity.h): the variance of the IMU's vibration velocity, and the
// non-holonomic and speed-model pseudo-measurements widened by it (ErrorStateEkf).
#include "hil/estimator/vibration_velocity.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hil/estimator/error_state_ekf.h"

namespace hil::estimator {
namespace {

constexpr double kDt = 0.01;  // 100 Hz
constexpr double kG = 9.81;

// body specific force at t: gravity, a slow forward acceleration and a ride sinusoid on x
Eigen::Vector3d Force(double t_s, double ride_mps2, double ride_hz) {
  return {0.2 * std::sin(0.05 * t_s) + ride_mps2 * std::sin(2 * M_PI * ride_hz * t_s), 0.0, kG};
}

Eigen::Vector3d VarianceAfter(VibrationVelocity& v, double seconds, double ride_mps2,
                              double ride_hz) {
  for (int k = 0; k < static_cast<int>(seconds / kDt); ++k)
    v.Add(Force(k * kDt, ride_mps2, ride_hz) * kDt, kDt);
  return v.variance_B_mps2();
}

TEST(VibrationVelocity, ARideSinusoidGivesItsVelocityVariance) {
  VibrationVelocity v(0.5, 2.0);
  const double a = 0.6, f = 5.0;
  const Eigen::Vector3d var = VarianceAfter(v, 30.0, a, f);
  // velocity amplitude a / (2πf), variance half its square; the high-pass gain at 5 Hz is 0.996
  const double fc = 1.0 / (2 * M_PI * 0.5);
  const double gain = (f / fc) * (f / fc) / (1 + (f / fc) * (f / fc));
  const double expected = 0.5 * std::pow(gain * a / (2 * M_PI * f), 2);
  EXPECT_NEAR(var.x(), expected, 0.15 * expected);
  // gravity and the slow acceleration are not vibration
  EXPECT_LT(var.y(), 1e-12);
  EXPECT_LT(var.z(), 1e-12);
}

TEST(VibrationVelocity, SlowMotionAloneIsNotVibration) {
  VibrationVelocity v(0.5, 2.0);
  const Eigen::Vector3d var = VarianceAfter(v, 30.0, 0.0, 0.0);
  // a 0.2 m/s² swing over two minutes leaves (0.2·0.05·τ²)² at most: far below 1 mm/s
  EXPECT_LT(var.x(), 1e-6);
}

TEST(VibrationVelocity, OffStaysZero) {
  VibrationVelocity v(0.0, 2.0);
  EXPECT_FALSE(v.enabled());
  EXPECT_EQ(VarianceAfter(v, 5.0, 0.6, 5.0), Eigen::Vector3d::Zero());
}

// The same lateral and forward velocity errors move the filter less when the IMU's vibration
// explains them.
TEST(VibrationVelocity, WidensTheNonHolonomicAndSpeedModelUpdates) {
  EkfParams p;
  p.nhc_std_mps = 0.02;
  p.speed_rw_mps_rthz = 0.009;
  p.speed_dev_std_mps = 0.005;
  p.init_vel_std_mps = 0.02;
  p.init_roll_pitch_std_rad = 1e-3;
  p.init_yaw_std_rad = 1e-3;
  // the corrections of the body velocity (x: speed model, y: NHC) for 3 cm/s off on both
  auto correction = [&](const Eigen::Vector3d& vibration_var_B) {
    ErrorStateEkf ekf(p, EarthModel{});
    NavState s;
    s.v_N_mps = Eigen::Vector3d(1.0, 0.0, 0.0);  // heading east: body x = east, y = north
    ekf.Initialize(s);
    ekf.ResetSetSpeed(0.001);
    ekf.mutable_state().v_N_mps = Eigen::Vector3d(1.03, 0.03, 0.0);
    ekf.SetVibrationVariance(vibration_var_B);
    EXPECT_TRUE(ekf.UpdateNonHolonomic().accepted);
    EXPECT_TRUE(ekf.UpdateSpeedModel().accepted);
    const Eigen::Vector3d v_B = ekf.state().q_NB.conjugate() * ekf.state().v_N_mps;
    return Eigen::Vector2d(1.03 - v_B.x(), 0.03 - v_B.y());
  };
  const Eigen::Vector2d plain = correction(Eigen::Vector3d::Zero());
  const Eigen::Vector2d widened = correction(Eigen::Vector3d::Constant(0.03 * 0.03));
  EXPECT_GT(plain.x(), 0.01);
  EXPECT_GT(plain.y(), 0.01);
  EXPECT_LT(widened.x(), 0.6 * plain.x());
  EXPECT_LT(widened.y(), 0.6 * plain.y());
}

}  // namespace
}  // namespace hil::estimator

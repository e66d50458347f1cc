// navd's EKF as the paper-000 robot's configuration has it (NEO-5M at 1 Hz, Razor IMU, 0.44 m/s):
// the set-up shared by the navigator tests of the fix velocity (GnssVelocityNoise, the INS's
// ripple at the fix instants). Each test switches its own feature on or off on top.
#pragma once

#include <chrono>

#include "hil/estimator/navigator.h"

namespace hil::estimator::test {

/// The robot's filter: no fusion delay, the Razor's noise, the NEO-5M's correlated error (τ 4.5 s,
/// 0.25 m per horizontal axis, 0.5 m up), the NHC at 5 cm/s.
inline NavigatorParams Paper000RobotParams() {
  NavigatorParams p;
  p.mode = NavMode::kEkf;
  p.fusion_horizon = std::chrono::nanoseconds{0};
  p.ekf.accel_noise_mps2_rthz = 0.0125;
  p.ekf.gyro_noise_radps_rthz = 0.002;
  p.ekf.init_pos_std_m = 0.3;
  p.ekf.init_vel_std_mps = 0.05;
  p.ekf.init_roll_pitch_std_rad = 0.01;
  p.ekf.init_yaw_std_rad = 0.05;
  p.ekf.gnss_error_tau_s = 4.5;
  p.ekf.gnss_error_std_m = 0.25;
  p.ekf.gnss_error_vertical_std_m = 0.5;
  p.ekf.nhc_std_mps = 0.05;
  return p;
}

}  // namespace hil::estimator::test

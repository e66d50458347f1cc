#pragma once
/// @file
/// The ground-truth state that every emulator samples: the contract between the truth integrator
/// (harness, SUNDIALS CVODE) and the device emulators (firmware_emu), which must not depend on
/// the harness.
///
/// Frames (fixed for the whole project):
///  - `N`: local tangent frame at the scenario origin, **ENU** (x east, y north, z up), origin on
///    the WGS-84 ellipsoid point (origin latitude, longitude, height).
///  - `E`: ECEF (WGS-84).
///  - `B`: vehicle body, **FLU** (x forward, y left, z up), origin at the vehicle reference point
///    (rear-axle centre for wheeled vehicles), on the ground.
///  - `I`: inertial frame, used for the IMU's angular rate when Earth rotation is enabled.
/// Notation: `p_NB_N_m` is the position of B's origin relative to N's origin, expressed in N, in
/// metres; `q_NB` rotates vectors from B to N (v_N = q_NB * v_B); `w_NB_B` is B's angular velocity
/// relative to N, expressed in B.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "hil/firmware_emu/sim_time.h"

namespace hil {

/// Standard gravity used wherever a nominal value is needed (m/s²).
inline constexpr double kStandardGravity_mps2 = 9.80665;

/// The true vehicle state at one instant.
struct TruthSample {
  Time t{};                         ///< scenario time
  double lat_deg = 0, lon_deg = 0;  ///< geodetic WGS-84 of the reference point
  double height_m = 0;              ///< ellipsoidal height of the reference point
  Eigen::Vector3d p_NB_N_m = Eigen::Vector3d::Zero();     ///< local ENU position
  Eigen::Vector3d p_EB_E_m = Eigen::Vector3d::Zero();     ///< ECEF position
  Eigen::Vector3d v_NB_N_mps = Eigen::Vector3d::Zero();   ///< velocity w.r.t. the ground, ENU
  Eigen::Vector3d a_NB_N_mps2 = Eigen::Vector3d::Zero();  ///< acceleration w.r.t. the ground, ENU
  Eigen::Quaterniond q_NB = Eigen::Quaterniond::Identity();  ///< attitude, body FLU → ENU
  Eigen::Vector3d w_NB_B_radps = Eigen::Vector3d::Zero();    ///< angular rate w.r.t. the ground
  Eigen::Vector3d w_IB_B_radps = Eigen::Vector3d::Zero();    ///< inertial angular rate (gyro truth)
  Eigen::Vector3d alpha_NB_B_radps2 = Eigen::Vector3d::Zero();  ///< angular acceleration
  /// Specific force at the reference point in B (what an ideal accelerometer there measures):
  /// f = R_BN (a + 2 Ω_IE × v − g), gravity included (normal gravity, which contains the
  /// centrifugal term), the Coriolis term only when the truth models Earth rotation; it reads +g
  /// on z when level and at rest.
  Eigen::Vector3d f_B_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d gravity_N_mps2{0, 0, -kStandardGravity_mps2};  ///< local gravity vector
  double speed_mps = 0;  ///< horizontal forward speed of the reference point (the model's v)
  double steer_rad = 0;  ///< front-wheel steering angle (bicycle models), left positive
  /// Rear (bicycle) or drive (differential) wheel ground speeds: v ∓ ψ̇ · track / 2.
  double wheel_speed_left_mps = 0, wheel_speed_right_mps = 0;
  double cross_track_m = 0;  ///< signed distance to the planned path, left positive
  double along_track_m = 0;  ///< arc length of the nearest planned-path point from its start
  double speed_cmd_mps = 0;  ///< forward speed commanded by the guidance (held between updates)
  double steer_cmd_rad = 0;  ///< steering angle commanded by the guidance (bicycle models)
};

}  // namespace hil

#pragma once
/// @file
/// navd's gyro + wheel-odometry EKF (paper 001's filter, seeds_001_003.md A.6): a planar
/// dead-reckoning filter for a differential-drive vehicle that fuses the IMU's yaw rate with the
/// wheel encoders and feeds the estimated gyro bias back into the heading propagation.
///
/// State x = [p_E, p_N, ψ, b] in the local ENU plane: position of the drive axle's midpoint (m),
/// yaw ψ (rad, counter-clockwise from east) and the gyro's yaw-rate bias b (rad/s).
/// - Gyro (each IMU sample, Δθ about the up axis over dt): ψ ← ψ + Δθ − b·dt; P gains the gyro's
///   angle random walk and the bias random walk.
/// - Odometry (each encoder interval): the distance Δs moves the position along the heading at the
///   interval's midpoint (ψ_mid), with the Jacobian ∂p/∂ψ = Δs·(−sin ψ_mid, cos ψ_mid); the
///   interval's wheel yaw change Δψ_odo = (Δs_R − Δs_L)/track is a measurement of the raw gyro
///   increment over the same interval minus the bias: z = Δψ_odo, h(x) = Δθ_raw − b·Δt,
///   H = [0, 0, 0, −Δt]. The bias so estimated corrects every later gyro sample (the feedback);
///   the heading follows through P's heading-bias covariance.
/// Fixed-size Eigen, no allocation.

#include <cmath>
#include <cstdint>

#include <Eigen/Core>

namespace hil::estimator::odometry {

struct GyroOdometryParams {
  double gyro_arw_rad_per_sqrt_s = 1.5e-4;      ///< gyro angle random walk (white rate noise)
  double gyro_bias_rw_radps_per_sqrt_s = 1e-5;  ///< bias random walk
  double init_bias_std_radps = 0.005;           ///< after the static alignment's mean
  double init_yaw_std_rad = 0.005, init_position_std_m = 0.01;
  double odo_yaw_std_rad = 0.004;           ///< Δψ_odo 1σ per interval (quantisation, slip)
  double odo_distance_std_fraction = 0.01;  ///< Δs 1σ as a fraction of Δs (scale, slip)
  double odo_lateral_std_fraction = 0.002;  ///< sideways slip, fraction of Δs
  double gate_chi2 = 25.0;  ///< a Δψ_odo innovation beyond this (1 dof) is rejected (wheel spin)
};

struct GyroOdometryStats {
  std::uint64_t gyro_samples = 0, odometry_updates = 0, odometry_rejected = 0;
};

class GyroOdometryFilter {
 public:
  using Vector4d = Eigen::Matrix<double, 4, 1>;
  using Matrix4d = Eigen::Matrix<double, 4, 4>;
  explicit GyroOdometryFilter(const GyroOdometryParams& p = {}) : params_(p) {}

  void Initialize(const Eigen::Vector2d& p_EN_m, double yaw_rad, double bias_radps);
  /// One gyro sample: Δθ about the up axis (rad, counter-clockwise) over dt_s.
  void PredictGyro(double delta_theta_up_rad, double dt_s);
  /// One encoder interval: distance of the axle midpoint and the wheels' yaw change, the raw gyro
  /// increment over the same interval, its length, and the heading at its midpoint
  /// (`yaw_mid_rad`, from the caller's heading history).
  void UpdateOdometry(double distance_m, double odo_delta_yaw_rad, double gyro_delta_theta_rad,
                      double interval_s, double yaw_mid_rad);

  /// The position part of an encoder interval alone (no gyro over it to compare with).
  void MovePosition(double distance_m, double yaw_mid_rad);

  bool initialized() const { return initialized_; }
  Eigen::Vector2d position() const { return x_.head<2>(); }
  double yaw_rad() const { return x_(2); }
  double bias_radps() const { return x_(3); }
  Eigen::Vector2d position_std_m() const { return P_.diagonal().head<2>().cwiseSqrt(); }
  double yaw_std_rad() const { return std::sqrt(P_(2, 2)); }
  double bias_std_radps() const { return std::sqrt(P_(3, 3)); }
  const GyroOdometryStats& stats() const { return stats_; }
  const GyroOdometryParams& params() const { return params_; }

 private:
  GyroOdometryParams params_;
  Vector4d x_ = Vector4d::Zero();
  Matrix4d P_ = Matrix4d::Identity();
  bool initialized_ = false;
  GyroOdometryStats stats_;
};

}  // namespace hil::estimator::odometry

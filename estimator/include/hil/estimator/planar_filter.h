#pragma once
/// @file
/// Seed 000's planar filter, kept as a comparison mode: a linear Kalman filter on the horizontal
/// position and velocity x = [p_E, p_N, v_E, v_N], driven by the body accelerations rotated to the
/// navigation frame with the heading integrated from the yaw gyro, x(k+1) = A x(k) + B u(k) + w,
/// updated with GNSS position (and velocity when present), y = C x + v. The heading starts from the
/// GNSS course (or the compass) and follows the yaw gyro, with a weak correction to the course.

#include <Eigen/Core>
#include <Eigen/LU>

namespace hil::estimator {

struct PlanarFilterParams {
  double accel_noise_mps2 = 0.3;  ///< acceleration input noise (1σ, per sample)
  double heading_gain = 0.05;     ///< fraction of the course−heading difference applied per fix
};

class PlanarFilter {
 public:
  explicit PlanarFilter(const PlanarFilterParams& p = {}) : params_(p) {}
  /// Starts from a position, velocity and heading (radians counter-clockwise from east).
  void Initialize(const Eigen::Vector2d& p_m, const Eigen::Vector2d& v_mps, double yaw_rad,
                  double pos_std_m);
  /// One IMU interval: body forward/left acceleration (m/s²) and yaw rate (rad/s).
  void Predict(double accel_fwd_mps2, double accel_left_mps2, double yaw_rate_radps, double dt_s);
  /// GNSS position (m) with 1σ per axis; optional velocity.
  void UpdatePosition(const Eigen::Vector2d& p_m, double std_m);
  void UpdateVelocity(const Eigen::Vector2d& v_mps, double std_mps);

  Eigen::Vector2d position() const { return x_.head<2>(); }
  Eigen::Vector2d velocity() const { return x_.tail<2>(); }
  double yaw_rad() const { return yaw_; }
  const Eigen::Matrix4d& covariance() const { return P_; }

 private:
  PlanarFilterParams params_;
  Eigen::Vector4d x_ = Eigen::Vector4d::Zero();
  Eigen::Matrix4d P_ = Eigen::Matrix4d::Identity();
  double yaw_ = 0;
};

}  // namespace hil::estimator

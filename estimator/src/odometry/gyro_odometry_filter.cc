#include "hil/estimator/odometry/gyro_odometry_filter.h"

#include <cmath>

namespace hil::estimator::odometry {

void GyroOdometryFilter::Initialize(const Eigen::Vector2d& p_EN_m, double yaw_rad,
                                    double bias_radps) {
  x_ << p_EN_m.x(), p_EN_m.y(), yaw_rad, bias_radps;
  P_.setZero();
  const double sp = params_.init_position_std_m;
  P_.diagonal() << sp * sp, sp * sp, params_.init_yaw_std_rad * params_.init_yaw_std_rad,
      params_.init_bias_std_radps * params_.init_bias_std_radps;
  initialized_ = true;
}

void GyroOdometryFilter::PredictGyro(double delta_theta_up_rad, double dt_s) {
  if (!initialized_ || !(dt_s > 0)) return;
  x_(2) += delta_theta_up_rad - x_(3) * dt_s;
  // F = I except ∂ψ/∂b = −dt
  Matrix4d F = Matrix4d::Identity();
  F(2, 3) = -dt_s;
  P_ = F * P_ * F.transpose();
  const double arw = params_.gyro_arw_rad_per_sqrt_s, brw = params_.gyro_bias_rw_radps_per_sqrt_s;
  P_(2, 2) += arw * arw * dt_s;
  P_(3, 3) += brw * brw * dt_s;
  ++stats_.gyro_samples;
}

void GyroOdometryFilter::MovePosition(double distance_m, double yaw_mid_rad) {
  const double c = std::cos(yaw_mid_rad), s = std::sin(yaw_mid_rad);
  x_(0) += distance_m * c;
  x_(1) += distance_m * s;
  Matrix4d F = Matrix4d::Identity();
  F(0, 2) = -distance_m * s;
  F(1, 2) = distance_m * c;
  P_ = F * P_ * F.transpose();
  const double along = params_.odo_distance_std_fraction * distance_m,
               side = params_.odo_lateral_std_fraction * distance_m;
  // along-track and sideways noise, rotated into E, N
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  const Eigen::Matrix2d Q =
      R * Eigen::Vector2d(along * along, side * side).asDiagonal() * R.transpose();
  P_.topLeftCorner<2, 2>() += Q;
}

void GyroOdometryFilter::UpdateOdometry(double distance_m, double odo_delta_yaw_rad,
                                        double gyro_delta_theta_rad, double interval_s,
                                        double yaw_mid_rad) {
  if (!initialized_ || !(interval_s > 0)) return;
  MovePosition(distance_m, yaw_mid_rad);
  Vector4d H = Vector4d::Zero();
  H(3) = -interval_s;
  const double innovation = odo_delta_yaw_rad - (gyro_delta_theta_rad - x_(3) * interval_s);
  const double r = params_.odo_yaw_std_rad * params_.odo_yaw_std_rad;
  const double s = H.dot(P_ * H) + r;
  if (innovation * innovation / s > params_.gate_chi2) {
    ++stats_.odometry_rejected;
    return;
  }
  const Vector4d K = P_ * H / s;
  x_ += K * innovation;
  const Matrix4d I_KH = Matrix4d::Identity() - K * H.transpose();
  P_ = I_KH * P_ * I_KH.transpose() + K * r * K.transpose();  // Joseph form
  ++stats_.odometry_updates;
}

}  // namespace hil::estimator::odometry

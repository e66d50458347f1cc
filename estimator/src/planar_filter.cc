#include "hil/estimator/planar_filter.h"

#include <cmath>

namespace hil::estimator {

void PlanarFilter::Initialize(const Eigen::Vector2d& p, const Eigen::Vector2d& v, double yaw,
                              double pos_std) {
  x_ << p, v;
  yaw_ = yaw;
  P_.setZero();
  P_.diagonal() << pos_std * pos_std, pos_std * pos_std, 0.04, 0.04;
}

void PlanarFilter::Predict(double accel_fwd_mps2, double accel_left_mps2, double yaw_rate,
                           double dt) {
  if (!(dt > 0) || !std::isfinite(accel_fwd_mps2) || !std::isfinite(accel_left_mps2) ||
      !std::isfinite(yaw_rate))
    return;
  yaw_ += yaw_rate * dt;
  const double c = std::cos(yaw_), s = std::sin(yaw_);
  // body acceleration rotated to the navigation frame; the paper's rotation term [[0,−θ̇],[θ̇,0]]·v
  // is already contained in what a body-fixed accelerometer measures (the centripetal acceleration)
  const Eigen::Vector2d a_N(c * accel_fwd_mps2 - s * accel_left_mps2,
                            s * accel_fwd_mps2 + c * accel_left_mps2);
  Eigen::Matrix4d A = Eigen::Matrix4d::Identity();
  A(0, 2) = A(1, 3) = dt;
  Eigen::Matrix<double, 4, 2> B;
  B << 0.5 * dt * dt, 0, 0, 0.5 * dt * dt, dt, 0, 0, dt;
  x_ = A * x_ + B * a_N;
  const double q = params_.accel_noise_mps2 * params_.accel_noise_mps2;
  P_ = A * P_ * A.transpose() + B * B.transpose() * q;
}

void PlanarFilter::UpdatePosition(const Eigen::Vector2d& p_m, double std_m) {
  if (!p_m.allFinite() || !(std_m > 0)) return;
  Eigen::Matrix<double, 2, 4> C = Eigen::Matrix<double, 2, 4>::Zero();
  C(0, 0) = C(1, 1) = 1;
  const Eigen::Matrix2d S = C * P_ * C.transpose() + Eigen::Matrix2d::Identity() * std_m * std_m;
  const Eigen::Matrix<double, 4, 2> K = P_ * C.transpose() * S.inverse();
  x_ += K * (p_m - C * x_);
  P_ = (Eigen::Matrix4d::Identity() - K * C) * P_;
}

void PlanarFilter::UpdateVelocity(const Eigen::Vector2d& v_mps, double std_mps) {
  if (!v_mps.allFinite() || !(std_mps > 0)) return;
  Eigen::Matrix<double, 2, 4> C = Eigen::Matrix<double, 2, 4>::Zero();
  C(0, 2) = C(1, 3) = 1;
  const Eigen::Matrix2d S =
      C * P_ * C.transpose() + Eigen::Matrix2d::Identity() * std_mps * std_mps;
  const Eigen::Matrix<double, 4, 2> K = P_ * C.transpose() * S.inverse();
  x_ += K * (v_mps - C * x_);
  P_ = (Eigen::Matrix4d::Identity() - K * C) * P_;
  // weak heading correction towards the course over ground when moving
  if (v_mps.norm() > 0.2) {
    const double course = std::atan2(v_mps.y(), v_mps.x());
    yaw_ += params_.heading_gain * std::remainder(course - yaw_, 2.0 * M_PI);
  }
}

}  // namespace hil::estimator

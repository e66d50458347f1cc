#include "hil/estimator/uwb/uwb_planar_filter.h"

#include <cmath>
#include <numbers>

#include <Eigen/LU>

namespace hil::estimator::uwb {
namespace {

double Wrap(double a) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  a = std::fmod(a, kTwoPi);
  if (a > std::numbers::pi) a -= kTwoPi;
  if (a <= -std::numbers::pi) a += kTwoPi;
  return a;
}

}  // namespace

void UwbPlanarFilter::Initialize(const Eigen::Vector2d& p_W_m, double yaw_rad) {
  x_ << p_W_m.x(), p_W_m.y(), Wrap(yaw_rad), 0.0, 0.0;
  const double sp = params_.position_std_m, sy = params_.yaw_std_rad;
  p_ = Matrix5d::Zero();
  p_.diagonal() << sp * sp, sp * sp, sy * sy,
      params_.init_speed_std_mps * params_.init_speed_std_mps,
      params_.init_bias_std_radps * params_.init_bias_std_radps;
  initialized_ = true;
  rejected_in_row_ = 0;
}

void UwbPlanarFilter::Predict(double yaw_rate_radps, double dt_s) {
  if (!initialized_ || !(dt_s > 0) || !std::isfinite(yaw_rate_radps)) return;
  const double psi = x_[2], v = x_[3], c = std::cos(psi), s = std::sin(psi);
  Matrix5d f = Matrix5d::Identity();
  f(0, 2) = -v * s * dt_s;
  f(0, 3) = c * dt_s;
  f(1, 2) = v * c * dt_s;
  f(1, 3) = s * dt_s;
  f(2, 4) = -dt_s;
  x_[0] += v * c * dt_s;
  x_[1] += v * s * dt_s;
  x_[2] = Wrap(psi + (yaw_rate_radps - x_[4]) * dt_s);
  Matrix5d q = Matrix5d::Zero();
  const double rn = params_.rate_noise_radps * dt_s;
  q(2, 2) = rn * rn;
  q(3, 3) = params_.speed_rw_mps2 * params_.speed_rw_mps2 * dt_s;
  q(4, 4) = params_.bias_rw_radps2 * params_.bias_rw_radps2 * dt_s;
  p_ = f * p_ * f.transpose() + q;
  ++stats_.predictions;
}

bool UwbPlanarFilter::UpdatePosition(const Eigen::Vector2d& p_W_m) {
  if (!initialized_) return false;
  const Eigen::Vector2d y = p_W_m - x_.head<2>();
  const double r = params_.position_std_m * params_.position_std_m;
  const Eigen::Matrix2d s = p_.topLeftCorner<2, 2>() + r * Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d s_inv = s.inverse();
  if (y.dot(s_inv * y) > params_.gate_chi2) {
    ++stats_.position_rejected;
    if (++rejected_in_row_ >= params_.reset_after_rejections) {
      Initialize(p_W_m, x_[2]);
      ++stats_.resets;
    }
    return false;
  }
  rejected_in_row_ = 0;
  const Eigen::Matrix<double, 5, 2> k = p_.leftCols<2>() * s_inv;
  x_ += k * y;
  x_[2] = Wrap(x_[2]);
  p_ = (Matrix5d::Identity() - k * Eigen::Matrix<double, 2, 5>::Identity()) * p_;
  p_ = 0.5 * (p_ + p_.transpose());
  ++stats_.position_updates;
  return true;
}

void UwbPlanarFilter::Update1(const Eigen::Matrix<double, 1, 5>& h, double innovation,
                              double variance) {
  const double s = (h * p_ * h.transpose())(0, 0) + variance;
  const Vector5d k = p_ * h.transpose() / s;
  x_ += k * innovation;
  x_[2] = Wrap(x_[2]);
  p_ = (Matrix5d::Identity() - k * h) * p_;
  p_ = 0.5 * (p_ + p_.transpose());
}

void UwbPlanarFilter::UpdateYaw(double yaw_rad) {
  if (!initialized_ || !std::isfinite(yaw_rad)) return;
  Eigen::Matrix<double, 1, 5> h = Eigen::Matrix<double, 1, 5>::Zero();
  h(0, 2) = 1.0;
  Update1(h, Wrap(yaw_rad - x_[2]), params_.yaw_std_rad * params_.yaw_std_rad);
  ++stats_.yaw_updates;
}

Eigen::Vector2d UwbPlanarFilter::position_std_m() const {
  return {std::sqrt(p_(0, 0)), std::sqrt(p_(1, 1))};
}

}  // namespace hil::estimator::uwb

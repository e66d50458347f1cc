#include "hil/estimator/uwb/uwb_planar_filter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

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
  x_.setZero();
  x_.head<3>() << p_W_m.x(), p_W_m.y(), Wrap(yaw_rad);
  const double sp = params_.position_std_m, sy = params_.yaw_std_rad, sr = params_.residual_std_m;
  const double sc = params_.yaw_offset_std_rad, sd = params_.yaw_drift_std_radps;
  p_ = Matrix9d::Zero();
  p_.diagonal() << sp * sp, sp * sp, sy * sy,
      params_.init_speed_std_mps * params_.init_speed_std_mps,
      params_.init_bias_std_radps * params_.init_bias_std_radps, sr * sr, sr * sr, sc * sc, sd * sd;
  // the fix holds its residual and the sensor's yaw its offset: the position's error is
  // −(r + white), the yaw's −(c + white) (see UpdatePosition, UpdateYaw)
  for (const auto& [state, offset, var] :
       {std::tuple{0, kResidual, sr * sr}, std::tuple{1, kResidual + 1, sr * sr},
        std::tuple{2, kYawOffset, sc * sc}}) {
    p_(state, state) += var;
    p_(state, offset) = p_(offset, state) = -var;
  }
  initialized_ = true;
  rejected_in_row_ = 0;
}

void UwbPlanarFilter::Predict(double yaw_rate_radps, double dt_s) {
  if (!initialized_ || !(dt_s > 0) || !std::isfinite(yaw_rate_radps)) return;
  const double psi = x_[2], v = x_[3], c = std::cos(psi), s = std::sin(psi);
  Matrix9d f = Matrix9d::Identity();
  f(0, 2) = -v * s * dt_s;
  f(0, 3) = c * dt_s;
  f(1, 2) = v * c * dt_s;
  f(1, 3) = s * dt_s;
  f(2, 4) = -dt_s;
  f(kYawOffset, kYawOffset + 1) = dt_s;
  x_[0] += v * c * dt_s;
  x_[1] += v * s * dt_s;
  x_[2] = Wrap(psi + (yaw_rate_radps - x_[4]) * dt_s);
  x_[kYawOffset] += x_[kYawOffset + 1] * dt_s;
  Matrix9d q = Matrix9d::Zero();
  const double rn = params_.rate_noise_radps * dt_s;
  q(2, 2) = rn * rn;
  q(3, 3) = params_.speed_rw_mps2 * params_.speed_rw_mps2 * dt_s;
  q(4, 4) = params_.bias_rw_radps2 * params_.bias_rw_radps2 * dt_s;
  q(kYawOffset, kYawOffset) = params_.yaw_drift_std_radps * params_.yaw_drift_std_radps * dt_s;
  p_ = f * p_ * f.transpose() + q;
  // the distance travelled as far as the speed is known: a tag standing still has a speed estimate
  // that wanders by its σ, and |v̂| alone summed to metres over a 2 min stop (the residual then
  // decayed into the position: mean NEES 2.6 after 2 min, 3.8 after 10)
  const double moving_mps = std::max(0.0, std::abs(v) - 2.0 * std::sqrt(p_(3, 3)));
  PredictResidual(moving_mps * dt_s);
  ++stats_.predictions;
}

void UwbPlanarFilter::PredictResidual(double distance_m) {
  const double sr2 = params_.residual_std_m * params_.residual_std_m;
  const double phi =
      params_.residual_distance_m > 0 ? std::exp(-distance_m / params_.residual_distance_m) : 0.0;
  x_.segment<2>(kResidual) *= phi;
  p_.middleRows<2>(kResidual) *= phi;
  p_.middleCols<2>(kResidual) *= phi;
  p_.block<2, 2>(kResidual, kResidual).diagonal().array() += sr2 * (1.0 - phi * phi);
}

bool UwbPlanarFilter::UpdatePosition(const Eigen::Vector2d& p_W_m) {
  if (!initialized_) return false;
  // z = p + r + white: H = [I₂ 0 0 0 I₂ 0 0]
  Eigen::Matrix<double, 2, kStates> h = Eigen::Matrix<double, 2, kStates>::Zero();
  h.leftCols<2>().setIdentity();
  h.middleCols<2>(kResidual).setIdentity();
  const Eigen::Vector2d y = p_W_m - x_.head<2>() - x_.segment<2>(kResidual);
  const double r = params_.position_std_m * params_.position_std_m;
  const Eigen::Matrix<double, kStates, 2> ph = p_ * h.transpose();
  const Eigen::Matrix2d s = h * ph + r * Eigen::Matrix2d::Identity();
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
  const Eigen::Matrix<double, kStates, 2> k = ph * s_inv;
  x_ += k * y;
  x_[2] = Wrap(x_[2]);
  p_ = (Matrix9d::Identity() - k * h) * p_;
  p_ = 0.5 * (p_ + p_.transpose());
  ++stats_.position_updates;
  return true;
}

void UwbPlanarFilter::Update1(const Eigen::Matrix<double, 1, kStates>& h, double innovation,
                              double variance) {
  const double s = (h * p_ * h.transpose())(0, 0) + variance;
  const Vector9d k = p_ * h.transpose() / s;
  x_ += k * innovation;
  x_[2] = Wrap(x_[2]);
  p_ = (Matrix9d::Identity() - k * h) * p_;
  p_ = 0.5 * (p_ + p_.transpose());
}

void UwbPlanarFilter::UpdateYaw(double yaw_rad) {
  if (!initialized_ || !std::isfinite(yaw_rad)) return;
  Eigen::Matrix<double, 1, kStates> h = Eigen::Matrix<double, 1, kStates>::Zero();
  h(0, 2) = 1.0;  // z = ψ + c + white
  h(0, kYawOffset) = 1.0;
  Update1(h, Wrap(yaw_rad - x_[2] - x_[kYawOffset]), params_.yaw_std_rad * params_.yaw_std_rad);
  ++stats_.yaw_updates;
}

Eigen::Vector2d UwbPlanarFilter::position_std_m() const {
  return {std::sqrt(p_(0, 0)), std::sqrt(p_(1, 1))};
}

}  // namespace hil::estimator::uwb

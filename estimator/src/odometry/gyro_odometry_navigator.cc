#include "hil/estimator/odometry/gyro_odometry_navigator.h"

#include <cmath>
#include <numbers>

namespace hil::estimator::odometry {
namespace {

double Seconds(Nanoseconds d) { return static_cast<double>(d.count()) * 1e-9; }

}  // namespace

void GyroOdometryNavigator::Align(const ImuSample& s) {
  align_dtheta_ += s.delta_angle_B_rad;
  align_dv_ += s.delta_velocity_B_mps;
  align_time_s_ += s.dt_s;
  if (align_time_s_ < config_.align_s || align_dv_.norm() <= 0) return;
  up_B_ = align_dv_.normalized();  // at rest the specific force points up
  const double bias = align_dtheta_.dot(up_B_) / align_time_s_;
  filter_.Initialize(config_.initial_p_EN_m, config_.initial_yaw_rad, bias);
}

void GyroOdometryNavigator::OnImu(const ImuSample& s) {
  if (!(s.dt_s > 0)) return;
  if (!filter_.initialized()) {
    Align(s);
    if (!filter_.initialized()) return;
    history_fill_ = 0;
  } else {
    const double dtheta = s.delta_angle_B_rad.dot(up_B_);
    filter_.PredictGyro(dtheta, s.dt_s);
    theta_raw_rad_ += dtheta;
    last_rate_radps_ = dtheta / s.dt_s - filter_.bias_radps();
  }
  history_[static_cast<std::size_t>(history_pos_)] = {s.t, theta_raw_rad_, filter_.yaw_rad()};
  history_pos_ = (history_pos_ + 1) % kHistory;
  if (history_fill_ < kHistory) ++history_fill_;
}

// The history at t, linearly between the two entries around it; false outside the history.
bool GyroOdometryNavigator::Lookup(GpsTime t, HistoryEntry& out) const {
  if (history_fill_ == 0) return false;
  const auto at = [&](int k) -> const HistoryEntry& {  // k = 0: the oldest entry
    return history_[static_cast<std::size_t>((history_pos_ - history_fill_ + k + kHistory) %
                                             kHistory)];
  };
  if (t < at(0).t || t > at(history_fill_ - 1).t) return false;
  for (int k = history_fill_ - 1; k > 0; --k) {
    const HistoryEntry &a = at(k - 1), &b = at(k);
    if (t < a.t) continue;
    const double span = Seconds(b.t - a.t);
    const double f = span > 0 ? Seconds(t - a.t) / span : 1.0;
    out = {t, a.theta_raw_rad + f * (b.theta_raw_rad - a.theta_raw_rad),
           a.yaw_rad + f * (b.yaw_rad - a.yaw_rad)};
    return true;
  }
  out = at(0);
  return true;
}

void GyroOdometryNavigator::OnEncoders(const EncoderSample& e) {
  ++stats_.encoder_samples;
  if (last_encoders_ && e.t <= last_encoders_->t) {
    ++stats_.out_of_order;
    return;
  }
  const std::optional<EncoderSample> prev = last_encoders_;
  last_encoders_ = e;
  if (!prev || !filter_.initialized()) return;
  // 32-bit wrapping counters: the difference modulo 2^32
  const auto delta = [](std::int32_t now, std::int32_t before) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(now) -
                                     static_cast<std::uint32_t>(before));
  };
  const double per_count = 2.0 * std::numbers::pi * config_.wheel_radius_m / config_.counts_per_rev;
  const double dl = delta(e.left_counts, prev->left_counts) * per_count,
               dr = delta(e.right_counts, prev->right_counts) * per_count;
  const double ds = 0.5 * (dl + dr), dpsi = (dr - dl) / config_.track_m;
  const double interval = Seconds(e.t - prev->t);
  speed_mps_ = ds / interval;
  HistoryEntry a, b, mid;
  if (!Lookup(prev->t, a) || !Lookup(e.t, b) || !Lookup(prev->t + (e.t - prev->t) / 2, mid)) {
    ++stats_.outside_history;  // no gyro over the interval: the position moves on the heading
    filter_.MovePosition(ds, filter_.yaw_rad());
    return;
  }
  filter_.UpdateOdometry(ds, dpsi, b.theta_raw_rad - a.theta_raw_rad, interval, mid.yaw_rad);
}

std::optional<PlanarSolution> GyroOdometryNavigator::Output(GpsTime t) const {
  if (!filter_.initialized()) return std::nullopt;
  PlanarSolution s;
  s.t = t;
  s.yaw_rad = filter_.yaw_rad();
  s.speed_mps = speed_mps_;
  s.yaw_rate_radps = last_rate_radps_;
  const double ahead =
      last_encoders_ && t > last_encoders_->t ? Seconds(t - last_encoders_->t) * speed_mps_ : 0.0;
  s.p_EN_m = filter_.position() + ahead * Eigen::Vector2d(std::cos(s.yaw_rad), std::sin(s.yaw_rad));
  s.position_std_m = filter_.position_std_m();
  s.yaw_std_rad = filter_.yaw_std_rad();
  s.bias_radps = filter_.bias_radps();
  return s;
}

}  // namespace hil::estimator::odometry

// Zero-velocity (ZUPT) and zero-angular-rate (ZARU) aid sources of the navigator's EKF: control
// (stationary detection, cadence) here, fusion in ErrorStateEkf::UpdateZeroVelocity and
// UpdateZeroAngularRate. See estimator.md, "Standing still".
#include <chrono>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::DetectStationary(const ImuSample& s) {
  const StationaryParams& sp = params_.stationary;
  if (!sp.enabled || params_.mode != NavMode::kEkf) return;
  stationary_.Add(s.delta_angle_B_rad, s.delta_velocity_B_mps, s.dt_s, ekf_.gyro_bias());
  // an IMU alone cannot tell standing from a constant velocity: the filter's speed and a recent
  // GNSS speed must agree
  const bool gnss_recent = last_gnss_vel_t_ && s.t - *last_gnss_vel_t_ <= std::chrono::seconds(2);
  const bool slow = ekf_.state().v_N_mps.head<2>().norm() < sp.max_speed_mps &&
                    (!gnss_recent || last_gnss_speed_mps_ < sp.max_gnss_speed_mps);
  const bool now = stationary_.still() && slow;
  if (now && !stationary_now_) ++stats_.stationary_periods;
  stationary_now_ = now;
  stats_.stationary = now;
  ekf_.SetAttitudeHold(now);
}

void Navigator::ControlZeroMotion() {
  if (!stationary_now_) return;
  const StationaryParams& sp = params_.stationary;
  if (filter_t_ - last_zupt_t_ >= params_.nhc_period - std::chrono::microseconds(1)) {
    Record(kAidZeroVelocity, ekf_.UpdateZeroVelocity(sp.zupt_std_mps));
    last_zupt_t_ = filter_t_;
  }
  if (stationary_.block_done()) {
    Record(kAidZeroAngularRate,
           ekf_.UpdateZeroAngularRate(stationary_.block_mean_rate_B_radps(),
                                      stationary_.block_mean_rate_std_radps()));
  }
}

}  // namespace hil::estimator

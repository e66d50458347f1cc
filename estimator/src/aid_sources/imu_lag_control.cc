// The IMU tag lag (ImuTimeOffset, imu_time_offset.h) in the navigator: every sample's heading
// increment and every fix's course go into the estimate; once it is conclusive the lag is taken
// off the IMU tags, slewed gradually (ImuTimeOffsetParams::slew_speed_mps; at most a tenth of a
// sample interval per sample, so that the tags stay in order). See estimator.md, "IMU time-tag
// lag".
#include <algorithm>
#include <cmath>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::CorrectImuTag(ImuSample& s) {
  if (params_.mode != NavMode::kEkf || !params_.imu_lag.enabled) return;
  if (aligned_) {
    // the heading increment about the local vertical, on the sample's own tag, the gyro
    // compensated as the filter's prediction does
    const Eigen::Vector3d up_B = ekf_.state().q_NB.conjugate() * Eigen::Vector3d::UnitZ();
    imu_lag_.AddImu(s.t, up_B.dot(ekf_.CompensatedAngle(s.delta_angle_B_rad, s.dt_s)));
  }
  stats_.imu_tag_lag_estimate_s = imu_lag_.best_lag_s();
  stats_.imu_tag_lag_std_s = imu_lag_.lag_std_s();
  const std::optional<double> lag = imu_lag_.lag_s();
  if (lag) {
    const auto target = Nanoseconds{static_cast<std::int64_t>(std::llround(*lag * 1e9))};
    const double speed = ekf_.state().v_N_mps.head<2>().norm();
    const double rate = std::min(0.1, params_.imu_lag.slew_speed_mps / std::max(speed, 1e-3));
    const auto slew = Nanoseconds{static_cast<std::int64_t>(s.dt_s * rate * 1e9)};
    const Nanoseconds step = std::clamp(target - imu_lag_applied_, -slew, slew);
    imu_lag_applied_ += step;
    // the tags move earlier by the step: the EKF's residual lag shrinks by as much
    ekf_.ShiftImuTags(-std::chrono::duration<double>(step).count());
    // the states learned against the old time base (z scale, couplings, residual lag): restart
    // them on the new one (ImuTimeOffsetParams::gyro_states_restart_s)
    const auto restart_after =
        Nanoseconds{std::llround(params_.imu_lag.gyro_states_restart_s * 1e9)};
    if (imu_lag_applied_ == target &&
        std::chrono::abs(imu_lag_applied_ - gyro_states_lag_) >= restart_after) {
      ekf_.RestartTimeBaseStates();
      gyro_states_lag_ = imu_lag_applied_;
    }
  }
  stats_.imu_tag_lag_s = std::chrono::duration<double>(imu_lag_applied_).count();
  s.t -= imu_lag_applied_;
}

void Navigator::ObserveGnssCourse(const GnssSample& g) {
  if (params_.mode != NavMode::kEkf || !params_.imu_lag.enabled) return;
  if (!g.has_velocity || g.fix_quality <= 0) return;
  imu_lag_.AddVelocity(g.t, g.vel_enu_mps.x(), g.vel_enu_mps.y(),
                       std::max(g.vel_std_enu_mps.x(), g.vel_std_enu_mps.y()));
}

}  // namespace hil::estimator

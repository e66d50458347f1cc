#pragma once
/// @file
/// Putting a raw IMU log on GPS time: the sensor's tick mapped to the time tags of the logger
/// (a straight-line fit of tag time on tick: the tags are arrival times, late by the logger's
/// latency, the tick is the sampling clock), then the remaining lag of the IMU against GNSS time
/// estimated by cross-correlating the gyro's heading rate with the GNSS course rate.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace hil::harness {

/// t = offset_s + scale · (tick − tick0) with residual statistics (tag minus fit).
struct ImuTickFit {
  double tick0_s = 0, offset_s = 0, scale = 1;
  double residual_rms_s = 0, residual_min_s = 0, residual_max_s = 0;
  double At(double tick_s) const { return offset_s + scale * (tick_s - tick0_s); }
};

/// Least-squares fit of `tag_s` on `tick_s` (same length, at least two).
ImuTickFit FitImuTicks(const std::vector<double>& tick_s, const std::vector<double>& tag_s);

/// One GNSS epoch as the lag estimator needs it: time (s) and NED velocity.
struct CourseEpoch {
  double t_s = 0;
  Eigen::Vector3d v_ned_mps = Eigen::Vector3d::Zero();
};

struct ImuLagEstimate {
  double lag_s = 0;           ///< the IMU's times are late by this much: true time = t − lag
  double correlation = 0;     ///< normalized correlation at the peak
  std::size_t intervals = 0;  ///< GNSS intervals used (both ends above the speed threshold)
};

/// Heading increments of the gyro (`yaw_rate_radps` at `imu_t_s`, the rate about the down axis)
/// against the course increments of consecutive GNSS epochs both faster than `min_speed_mps`,
/// for trial lags in [−max_lag_s, max_lag_s] by 1 ms; parabolic refinement around the peak.
/// @throws std::runtime_error when fewer than 10 intervals qualify.
ImuLagEstimate EstimateImuLag(const std::vector<double>& imu_t_s,
                              const std::vector<double>& yaw_rate_radps,
                              const std::vector<CourseEpoch>& gnss, double max_lag_s,
                              double min_speed_mps);

}  // namespace hil::harness

#pragma once
/// @file
/// Initial attitude and sensor errors of a real IMU log, from the data: the IMU at rest at the
/// start (GNSS speed below a threshold) gives the gyro bias (mean rate), roll and pitch (mean
/// specific force against gravity) and the accelerometer bias along gravity (|f| − normal
/// gravity); the yaw is the rotation about the vertical that best maps the IMU's velocity
/// increments (strapdown from that roll and pitch, yaw 0, bias removed) onto the GNSS velocity
/// increments over the first seconds of motion (a closed-form least squares); the mounting yaw
/// (body x against the course) is the mean difference of course and heading while moving.
/// Body axes FRD, navigation frame NED.

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "hil/harness/datasets/imu_timing.h"

namespace hil::harness {

/// One IMU sample on GPS time, body FRD.
struct TimedImuSample {
  double t_s = 0;
  Eigen::Vector3d w_frd_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d f_frd_mps2 = Eigen::Vector3d::Zero();
};

struct ImuAlignment {
  double static_from_s = 0, static_to_s = 0;  ///< the rest period used
  Eigen::Vector3d f_static_frd_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_frd_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_frd_mps2 = Eigen::Vector3d::Zero();  ///< along gravity only
  double roll_rad = 0, pitch_rad = 0, yaw_rad = 0;                ///< at static_from_s
  double yaw_fit_from_s = 0, yaw_fit_to_s = 0;
  std::size_t yaw_fit_intervals = 0;
  double mount_yaw_rad = 0;  ///< mean course − heading while faster than the threshold
  std::size_t mount_yaw_epochs = 0;
};

struct AlignmentOptions {
  double rest_speed_mps = 0.1;  ///< GNSS speed below which the start counts as rest
  double min_rest_s = 2;
  double motion_speed_mps = 0.5;  ///< for the mounting yaw
  double yaw_fit_s = 20;          ///< seconds of motion after the rest used for the yaw
  double normal_gravity_mps2 = 9.80665;
};

/// @param gnss GNSS epochs (times on the same clock as the IMU, NED velocity) in time order.
/// @throws std::runtime_error when the log does not start at rest or has too little motion.
ImuAlignment AlignImu(const std::vector<TimedImuSample>& imu, const std::vector<CourseEpoch>& gnss,
                      const AlignmentOptions& o);

/// NED-from-FRD rotation of roll, pitch, yaw (ZYX).
Eigen::Matrix3d NedFromFrd(double roll, double pitch, double yaw);

/// Normal gravity (WGS-84 Somigliana closed form with the free-air term) at a latitude and height.
double NormalGravity(double lat_deg, double height_m);

}  // namespace hil::harness

// The gyros' scale-factor errors, the x and y gyros' coupling to the z rate, the IMU tags'
// residual lag and the accelerometer's lateral-force errors as the EKF estimates them
// (ErrorStateEkf, kGyroScaleZ, kGyroCouplingX/Y, kImuTimeResidual,
// kAccelScaleY/CouplingXY/CouplingZY; estimator.md, "The z gyro's scale factor", "The residual tag
// lag and the x and y gyros' coupling", "The accelerometer in the turns"): copied into the
// navigator's statistics for the host's health line.
#include <algorithm>
#include <cmath>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::RecordGyroScale() {
  const auto std_of = [this](int i) { return std::sqrt(std::max(0.0, ekf_.covariance()(i, i))); };
  stats_.gyro_scale_z_estimated = ekf_.params().gyro_scale_z_std > 0;
  if (stats_.gyro_scale_z_estimated) {
    stats_.gyro_scale_z = ekf_.gyro_scale_z();
    stats_.gyro_scale_z_std = std_of(ekf_index::kGyroScaleZ);
  }
  stats_.gyro_scale_xy_estimated = ekf_.gyro_scale_xy_estimated();
  if (stats_.gyro_scale_xy_estimated) {
    stats_.gyro_scale_xy = ekf_.gyro_scale_xy();
    stats_.gyro_scale_xy_std = {std_of(ekf_index::kGyroScaleX), std_of(ekf_index::kGyroScaleY)};
  }
  stats_.imu_time_residual_s = ekf_.imu_time_residual_s();
  stats_.gyro_z_coupling_estimated = ekf_.gyro_z_coupling_estimated();
  if (stats_.gyro_z_coupling_estimated) {
    stats_.gyro_z_coupling_rad = ekf_.gyro_z_coupling_rad();
    stats_.gyro_z_coupling_std_rad = {std_of(ekf_index::kGyroCouplingX),
                                      std_of(ekf_index::kGyroCouplingY)};
  }
  stats_.accel_y_force_estimated = ekf_.accel_y_force_estimated();
  if (stats_.accel_y_force_estimated) {
    stats_.accel_y_force = ekf_.accel_y_force_error();
    stats_.accel_y_force_std = {std_of(ekf_index::kAccelScaleY),
                                std_of(ekf_index::kAccelCouplingXY),
                                std_of(ekf_index::kAccelCouplingZY)};
  }
}

}  // namespace hil::estimator

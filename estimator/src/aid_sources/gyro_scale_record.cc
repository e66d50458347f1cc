// The z gyro's scale-factor error as the EKF estimates it from the headland turns (ErrorStateEkf,
// kGyroScaleZ; estimator.md, "The z gyro's scale factor"): copied into the navigator's statistics
// for the host's health line.
#include <algorithm>
#include <cmath>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::RecordGyroScale() {
  stats_.gyro_scale_z_estimated = ekf_.params().gyro_scale_z_std > 0;
  if (!stats_.gyro_scale_z_estimated) return;
  stats_.gyro_scale_z = ekf_.gyro_scale_z();
  stats_.gyro_scale_z_std =
      std::sqrt(std::max(0.0, ekf_.covariance()(ekf_index::kGyroScaleZ, ekf_index::kGyroScaleZ)));
}

}  // namespace hil::estimator

// The IMU's mounting angles against the vehicle, as the EKF estimates them from the
// non-holonomic constraint (ErrorStateEkf, kMountPitch / kMountYaw; estimator.md, "The IMU's
// mounting angles"): copied into the navigator's statistics for the host's health line.
#include <algorithm>
#include <cmath>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::RecordMountAngles() {
  stats_.mount_estimated = ekf_.mount_angles_estimated();
  if (!stats_.mount_estimated) return;
  const EkfMatrix& P = ekf_.covariance();
  stats_.mount_pitch_rad = ekf_.mount_angles_rad().y();
  stats_.mount_yaw_rad = ekf_.mount_angles_rad().z();
  stats_.mount_pitch_std_rad =
      std::sqrt(std::max(0.0, P(ekf_index::kMountPitch, ekf_index::kMountPitch)));
  stats_.mount_yaw_std_rad =
      std::sqrt(std::max(0.0, P(ekf_index::kMountYaw, ekf_index::kMountYaw)));
}

}  // namespace hil::estimator

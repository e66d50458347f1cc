#include "hil/estimator/vibration_velocity.h"

namespace hil::estimator {

void VibrationVelocity::Add(const Eigen::Vector3d& delta_velocity_B_mps, double dt_s) {
  if (!enabled() || !(dt_s > 0)) return;
  const Eigen::Vector3d f_B = delta_velocity_B_mps / dt_s;
  if (!started_) {
    // start at the first sample's force: gravity is not a step
    mean_f_B_mps2_ = f_B;
    started_ = true;
  }
  const double a = dt_s / (tau_s_ + dt_s);
  mean_f_B_mps2_ += a * (f_B - mean_f_B_mps2_);
  v_B_mps_ = (1.0 - a) * v_B_mps_ + (f_B - mean_f_B_mps2_) * dt_s;
  const double b = dt_s / (mean_tau_s_ + dt_s);
  var_B_mps2_ += b * (v_B_mps_.cwiseProduct(v_B_mps_) - var_B_mps2_);
}

}  // namespace hil::estimator

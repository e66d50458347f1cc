#include "hil/estimator/accel_scatter.h"

#include <algorithm>

namespace hil::estimator {

void AccelScatter::Add(const Eigen::Vector3d& delta_velocity_B_mps, double dt_s) {
  if (!enabled() || !(dt_s > 0) || dt_s < min_dt_s_ * 0.999) return;
  const Eigen::Vector3d f = delta_velocity_B_mps / dt_s;
  if (samples_ >= 1) {
    // per axis σ² · dt, from the first difference's 2 σ² of white noise
    const Eigen::Vector3d sample = (f - f1_).cwiseAbs2() / 2.0 * dt_s;
    const double a = samples_ == 1 ? 1.0 : std::min(1.0, dt_s / tau_s_);
    axes_ += a * (sample - axes_);
  }
  f1_ = f;
  ++samples_;
}

}  // namespace hil::estimator

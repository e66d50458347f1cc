// The accelerometer's noise against the GNSS velocity innovations (ImuNoiseParams in
// navigator.h; estimator.md, "An IMU outside its noise model").
#include <algorithm>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::AdaptAccelNoise() {
  const ImuNoiseParams& p = params_.imu_noise;
  InnovationMonitor& m = monitors_[kAidGnssVelocity];
  if (!p.enabled || params_.mode != NavMode::kEkf || !m.window_full()) return;
  const double mean = m.window_mean_nis_per_dof();
  double scale = ekf_.accel_noise_scale();
  if (mean > p.raise_nis_per_dof && m.window_median_nis_per_dof() > p.raise_nis_per_dof) {
    // most velocity fixes miss by far more than the accelerometer's model allows
    const double step = std::clamp(m.window_mean_excess(), 1.0, p.max_step);
    scale = std::min(scale * step, p.max_scale);
    ++stats_.accel_noise_raises;
    m.ClearWindow();
  } else if (mean < 1.0 && scale > 1.0) {
    // the raised noise overstates the errors now: back towards the configured noise
    scale = std::max(1.0, scale * std::max(mean, 1.0 / p.max_step));
    m.ClearWindow();
  }
  ekf_.SetAccelNoiseScale(scale);
  stats_.accel_noise_scale = scale;
}

}  // namespace hil::estimator

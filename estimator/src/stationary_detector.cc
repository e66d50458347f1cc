#include "hil/estimator/stationary_detector.h"

#include <algorithm>
#include <cmath>

namespace hil::estimator {

void StationaryDetector::Reset() {
  sums_ = {};
  still_run_ = 0;
  still_ = false;
  block_done_ = false;
}

void StationaryDetector::Add(const Eigen::Vector3d& delta_angle_B_rad,
                             const Eigen::Vector3d& delta_velocity_B_mps, double dt_s,
                             const Eigen::Vector3d& gyro_bias_B_radps) {
  block_done_ = false;
  if (!p_.enabled || !(dt_s > 0)) return;
  const Eigen::Vector3d f = delta_velocity_B_mps / dt_s;
  const Eigen::Vector3d w = delta_angle_B_rad / dt_s;
  // thresholds from the configured per-sample noise σ, at least their floors
  thr_f_ = std::max(p_.accel_std_floor_mps2, p_.noise_factor * accel_noise_ / std::sqrt(dt_s));
  thr_w_ = std::max(p_.gyro_std_floor_radps, p_.noise_factor * gyro_noise_ / std::sqrt(dt_s));
  if (still_) {
    const double df = (f - last_mean_f_).cwiseAbs().maxCoeff();
    const double dw = (w - block_mean_w_).cwiseAbs().maxCoeff();
    if (df > p_.exit_factor * thr_f_ || dw > p_.exit_factor * thr_w_) {
      Reset();
      return;
    }
  }
  sums_.f += f;
  sums_.f2 += f.cwiseProduct(f);
  sums_.w += w;
  sums_.w2 += w.cwiseProduct(w);
  sums_.t += dt_s;
  ++sums_.n;
  if (sums_.t >= p_.block_s - 1e-9) EndBlock(gyro_bias_B_radps, dt_s);
}

void StationaryDetector::EndBlock(const Eigen::Vector3d& gyro_bias_B_radps, double dt_s) {
  const double n = static_cast<double>(sums_.n);
  const Eigen::Vector3d mean_f = sums_.f / n;
  const Eigen::Vector3d mean_w = sums_.w / n;
  const Eigen::Vector3d var_f = (sums_.f2 / n - mean_f.cwiseProduct(mean_f)).cwiseMax(0.0);
  const Eigen::Vector3d var_w = (sums_.w2 / n - mean_w.cwiseProduct(mean_w)).cwiseMax(0.0);
  const bool quiet = sums_.n >= 3 && var_f.maxCoeff() < thr_f_ * thr_f_ &&
                     var_w.maxCoeff() < thr_w_ * thr_w_ &&
                     (mean_w - gyro_bias_B_radps).cwiseAbs().maxCoeff() < p_.max_rate_radps;
  still_run_ = quiet ? still_run_ + 1 : 0;
  still_ = still_run_ >= p_.still_blocks;
  if (quiet) {
    last_mean_f_ = mean_f;
    block_mean_w_ = mean_w;
    // σ of the mean: the block's own scatter (vibration included) or the configured noise
    const double sigma_w = std::max(std::sqrt(var_w.maxCoeff()), gyro_noise_ / std::sqrt(dt_s));
    block_mean_w_std_ = std::max(p_.zaru_std_floor_radps, sigma_w / std::sqrt(n));
    block_done_ = still_;
  }
  sums_ = {};
}

}  // namespace hil::estimator

#include "hil/estimator/drivers/imu_increments.h"

namespace hil::estimator::drivers {

std::optional<ImuSample> ImuIncrements::Add(GpsTime t, const Eigen::Vector3d& w_B_radps,
                                            const Eigen::Vector3d& f_B_mps2,
                                            std::optional<double> dt_s) {
  std::optional<ImuSample> out;
  if (have_prev_) {
    const double dt = dt_s ? *dt_s : static_cast<double>((t - prev_t_).count()) * 1e-9;
    if (dt > 0 && dt <= max_gap_s_) {
      ImuSample s;
      s.t = t;
      s.dt_s = dt;
      s.delta_angle_B_rad = 0.5 * (prev_w_ + w_B_radps) * dt;
      s.delta_velocity_B_mps = 0.5 * (prev_f_ + f_B_mps2) * dt;
      out = s;
      ++increments_;
    } else {
      ++gaps_;
    }
  }
  have_prev_ = true;
  prev_t_ = t;
  prev_w_ = w_B_radps;
  prev_f_ = f_B_mps2;
  return out;
}

}  // namespace hil::estimator::drivers

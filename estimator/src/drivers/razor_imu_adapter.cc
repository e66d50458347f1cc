#include "hil/estimator/drivers/razor_imu_adapter.h"

#include <cmath>

namespace hil::estimator::drivers {

void RazorImuAdapter::AddGnssArrival(std::int64_t host_ns, GpsNs tov, double latency_s) {
  clock_.AddReference(host_ns - static_cast<std::int64_t>(std::llround(latency_s * 1e9)), tov);
  ++stats_.gnss_references;
}

std::optional<ImuSample> RazorImuAdapter::Add(const RazorTextSample& line, std::int64_t host_ns) {
  const Eigen::Vector3d w = RazorGyro_radps(line, scales_), f = RazorAccel_mps2(line, scales_);
  const auto measured = clock_.ToGps(host_ns);
  if (!measured) {
    ++stats_.imu_no_time;
    have_prev_ = false;
    return std::nullopt;
  }
  const GpsNs t = timer_.Add(*measured);
  std::optional<ImuSample> out;
  if (have_prev_) {
    const double dt = static_cast<double>(t - prev_t_) * 1e-9;
    if (dt > 0 && dt <= max_gap_s_) {
      ImuSample s;
      s.t = t;
      s.dt_s = dt;
      s.delta_angle_B_rad = 0.5 * (prev_w_ + w) * dt;
      s.delta_velocity_B_mps = 0.5 * (prev_f_ + f) * dt;
      out = s;
      ++stats_.imu_out;
    } else {
      ++stats_.imu_gap;
    }
  }
  have_prev_ = true;
  prev_t_ = t;
  prev_w_ = w;
  prev_f_ = f;
  return out;
}

}  // namespace hil::estimator::drivers

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
    increments_.Restart();
    return std::nullopt;
  }
  const GpsNs t = timer_.Add(*measured);
  const std::uint64_t gaps_before = increments_.gaps();
  auto out = increments_.Add(t, w, f);
  if (out) ++stats_.imu_out;
  if (increments_.gaps() != gaps_before) ++stats_.imu_gap;
  return out;
}

}  // namespace hil::estimator::drivers

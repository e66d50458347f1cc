#include "hil/estimator/drivers/razor_imu_adapter.h"

#include <cmath>

#include "hil/estimator/drivers/arrival_stamped_imu.h"

namespace hil::estimator::drivers {

void RazorImuAdapter::AddGnssArrival(std::int64_t host_ns, GpsNs tov, double latency_s) {
  clock_.AddReference(host_ns - static_cast<std::int64_t>(std::llround(latency_s * 1e9)), tov);
  ++stats_.gnss_references;
}

std::optional<ImuSample> RazorImuAdapter::Add(const RazorTextSample& line, std::int64_t host_ns) {
  const Eigen::Vector3d w = RazorGyro_radps(line, scales_), f = RazorAccel_mps2(line, scales_);
  const auto measured = clock_.ToGps(host_ns);
  return AddArrivalStamped(measured, w, f, timer_, increments_, stats_);
}

}  // namespace hil::estimator::drivers

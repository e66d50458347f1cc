#include "hil/estimator/drivers/arrival_imu_increments.h"

namespace hil::estimator::drivers {

std::optional<ImuSample> ArrivalImuIncrements::Add(const ArrivalClock& clock, std::int64_t host_ns,
                                                   const Eigen::Vector3d& w_B_radps,
                                                   const Eigen::Vector3d& f_B_mps2,
                                                   ArrivalImuCounts& counts) {
  const std::optional<GpsTime> measured = clock.ToGps(host_ns);
  if (!measured) {
    ++counts.imu_no_time;
    increments_.Restart();
    return std::nullopt;
  }
  const GpsTime t = timer_.Add(*measured);
  const std::uint64_t gaps_before = increments_.gaps();
  std::optional<ImuSample> out = increments_.Add(t, w_B_radps, f_B_mps2);
  if (out) ++counts.imu_out;
  if (increments_.gaps() != gaps_before) ++counts.imu_gap;
  return out;
}

}  // namespace hil::estimator::drivers

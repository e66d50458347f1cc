#pragma once
/// @file
/// IMU increments for rate samples that carry no time of their own (the Razor's text lines, J1939
/// ARI + ACCS on CAN): the host instant of each sample is mapped onto GPS time (ArrivalClock),
/// smoothed over the periodic stream (PeriodicSampleTimer) and integrated (ImuIncrements). Samples
/// before the map exists, or across a gap longer than `max_gap_s`, are counted and dropped.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/drivers/arrival_clock.h"
#include "hil/estimator/drivers/imu_increments.h"
#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

/// Counters of an arrival-timed IMU stream (part of each input's statistics).
struct ArrivalImuCounts {
  std::uint64_t imu_out = 0;      ///< increments produced
  std::uint64_t imu_no_time = 0;  ///< samples before the arrival clock had a map
  std::uint64_t imu_gap = 0;      ///< gaps that restarted the integration
};

class ArrivalImuIncrements {
 public:
  explicit ArrivalImuIncrements(double max_gap_s) : timer_(max_gap_s), increments_(max_gap_s) {}
  /// A sample of rate `w_B_radps` and specific force `f_B_mps2` taken at host instant `host_ns`
  /// (arrival minus any known latency); an IMU sample when it completes an interval.
  std::optional<ImuSample> Add(const ArrivalClock& clock, std::int64_t host_ns,
                               const Eigen::Vector3d& w_B_radps, const Eigen::Vector3d& f_B_mps2,
                               ArrivalImuCounts& counts);
  /// Restarts the tracker and the integration (the sender reset).
  void Reset() {
    timer_.Reset();
    increments_.Restart();
  }

 private:
  PeriodicSampleTimer timer_;
  ImuIncrements increments_;
};

}  // namespace hil::estimator::drivers

#pragma once
/// @file
/// The step the IMU inputs that carry no sample time share (J1939 frames on CAN, Razor text
/// lines): a rate sample stamped with its arrival, mapped onto GPS time by an `ArrivalClock`, is
/// smoothed by a `PeriodicSampleTimer` and integrated into increments by `ImuIncrements`.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/drivers/arrival_clock.h"
#include "hil/estimator/drivers/imu_increments.h"
#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

/// One rate sample measured at `measured` (its arrival on GPS time; nullopt while the arrival clock
/// has no map: counted in `stats.imu_no_time`, and the increments restart). Counts the increments
/// in `stats.imu_out` and the gaps in `stats.imu_gap`.
template <typename Stats>
std::optional<ImuSample> AddArrivalStamped(std::optional<GpsNs> measured,
                                           const Eigen::Vector3d& w_B_radps,
                                           const Eigen::Vector3d& f_B_mps2,
                                           PeriodicSampleTimer& timer, ImuIncrements& increments,
                                           Stats& stats) {
  if (!measured) {
    ++stats.imu_no_time;
    increments.Restart();
    return std::nullopt;
  }
  const GpsNs t = timer.Add(*measured);
  const std::uint64_t gaps_before = increments.gaps();
  auto out = increments.Add(t, w_B_radps, f_B_mps2);
  if (out) ++stats.imu_out;
  if (increments.gaps() != gaps_before) ++stats.imu_gap;
  return out;
}

}  // namespace hil::estimator::drivers

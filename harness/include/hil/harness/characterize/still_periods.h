#pragma once
/// @file
/// Still periods of an IMU log: the resampled log cut into windows; a window is still when the
/// standard deviation of every gyro axis and every accelerometer axis within it is below its
/// threshold (a body at rest shows sensor noise only; walking or driving shows tens of °/s and
/// m/s²). Runs of still windows, less one window at each end (the transitions), that last at
/// least `min_length_s` are the still periods.

#include <cstddef>
#include <vector>

#include "hil/harness/characterize/imu_series.h"

namespace hil::harness {

/// Thresholds: chosen here, not from a source. 0.5 °/s and 0.1 m/s² are 10-100 × the per-sample
/// noise of consumer MEMS at 100-200 Hz and far below the motion of a person or a vehicle.
struct StillOptions {
  double window_s = 1.0;
  double gyro_std_radps = 0.5 * 3.14159265358979323846 / 180.0;
  double accel_std_mps2 = 0.1;
  double min_length_s = 5.0;
};

struct StillPeriod {
  std::size_t first = 0, count = 0;  ///< cells of the UniformImu
  double from_s = 0, to_s = 0;       ///< seconds from the log's start
};

/// The still periods in time order. @throws std::invalid_argument for a window shorter than two
/// cells.
std::vector<StillPeriod> FindStillPeriods(const UniformImu& u, const StillOptions& o);

}  // namespace hil::harness

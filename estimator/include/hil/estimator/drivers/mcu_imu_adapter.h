#pragma once
/// @file
/// Turns decoded MCU frames into estimator samples on GPS time: STATUS gives the LSB scales (IMU
/// frames before the first STATUS are counted and dropped), TIME_PULSE feeds the ClockSync, and
/// each IMU_SAMPLE becomes an ImuSample whose interval runs from the previous sample (trapezoidal
/// increments of the sampled rates). Samples before the first valid time pulse, and across a gap
/// longer than `max_gap_s`, are dropped (the latter restarts the interval). MCU resets (a STATUS
/// with sequence 0) restart the clock mapping.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/clock_sync.h"
#include "hil/estimator/drivers/imu_increments.h"
#include "hil/estimator/drivers/mcu_frame_decoder.h"
#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

struct McuAdapterStats {
  std::uint64_t imu_out = 0, imu_no_scale = 0, imu_no_time = 0, imu_gap = 0, resets = 0, pulses = 0;
};

class McuImuAdapter {
 public:
  explicit McuImuAdapter(double max_gap_s = 0.5) : increments_(max_gap_s) {}
  /// Consumes one frame; returns an IMU sample when the frame completes one.
  std::optional<ImuSample> Add(const McuFrame& frame);
  const ClockSync& clock() const { return clock_; }
  const McuAdapterStats& stats() const { return stats_; }

 private:
  ClockSync clock_;
  ImuIncrements increments_;
  float accel_scale_ = 0, gyro_scale_ = 0;
  std::int64_t prev_tick_ = 0;  ///< the interval by the MCU's own clock
  McuAdapterStats stats_;
};

}  // namespace hil::estimator::drivers

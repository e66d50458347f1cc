#pragma once
/// @file
/// The navd.conf a run writes for navd: what the estimator section asks (mode, the scenario's
/// navd_input and navd_filter keys, the output) around what each row of the device table
/// contributes (device_kind.h: its navd_keys, written at its NavdConfSlot).

#include <string>

#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

/// The scenario's own [input] merge_window_s for navd (estimator.navd_input), -1 when it sets none.
double NavdMergeWindowS(const Scenario& s);
/// navd_mode gyro_odometry: the FIFO in the run folder the controller forwards the base's encoder
/// counts into for navd ([odometry] device), {odometry_fifo} in the controller's command.
inline constexpr const char* kOdometryFifo = "odometry.fifo";

/// The navd configuration for this scenario (input devices, leap seconds, mode, JSON output);
/// `gnss_device` is the first receiver's link in the run folder. `merge_window_s` > 0: [input]
/// merge_window_s (unless the scenario's navd_input sets it). @throws OutputWriteError.
void WriteNavdConfig(const std::string& path, const Scenario& s, const std::string& gnss_device,
                     double merge_window_s = 0);

}  // namespace hil::harness

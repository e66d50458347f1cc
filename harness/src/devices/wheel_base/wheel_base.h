#pragma once
// navd.conf's [odometry] section for estimator.navd_mode gyro_odometry (paper 001): navd's gyro +
// wheel-odometry mode reads the base's encoder counts from the FIFO the controller forwards them
// into (kOdometryFifo in the run folder, {odometry_fifo} in the controller's command).
#include <ostream>
#include <string>

#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

inline constexpr const char* kOdometryFifo = "odometry.fifo";

/// Writes [odometry]: the FIFO, the base's wheels, the origin, the start pose, and the scenario's
/// estimator.navd_filter keys (in this mode they tune the odometry filter).
void WriteNavdOdometry(std::ostream& out, const Scenario& s, const std::string& run_dir);

}  // namespace hil::harness

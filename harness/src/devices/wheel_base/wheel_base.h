#pragma once
// Internal to the devices stage: the wheel base's navd.conf writer for its row.
#include <ostream>
#include <string>

#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// At NavdConfSlot::kSections, for estimator.navd_mode gyro_odometry (paper 001): [odometry], the
/// FIFO the controller forwards the base's encoder counts into (kOdometryFifo, navd_conf.h), the
/// base's wheels, the origin, the start pose, and the scenario's estimator.navd_filter keys (in
/// this mode they tune the odometry filter). @throws std::runtime_error without a closed loop.
void WriteWheelBaseNavd(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                        std::ostream& out);

}  // namespace hil::harness

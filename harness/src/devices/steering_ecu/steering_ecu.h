#pragma once
// Internal to the harness run stage: the closed loop's ISOBUS steering ECU for BuildDevices.
#include <string>

#include "hil/harness/run/device_set.h"

namespace hil::harness {

/// Adds the steering ECU of a closed loop on the isobus channel (nothing otherwise): on the run's
/// CAN bus (transport socketcan) or behind a serial SLCAN adapter on RUN_DIR/<link> (slcan).
void AddIsobusSteering(const Scenario& s, const std::string& dir, DeviceSet& set);

}  // namespace hil::harness

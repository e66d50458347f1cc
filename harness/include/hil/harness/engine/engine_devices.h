#pragma once
/// @file
/// What the engine drives: the devices and the links they talk through, as a run
/// (run/device_set.h) or a replay built them. The engine owns none of it.

#include <memory>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/harness/links/can_endpoint.h"
#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {

struct EngineDevices {
  std::vector<std::unique_ptr<Device>>& devices;
  /// endpoints[i][p] is serial port p of devices[i]
  std::vector<std::vector<std::unique_ptr<SerialEndpoint>>>& endpoints;
  /// The CAN bus every device's DeviceOutput::can frames go out on; null without one.
  CanEndpoint* can = nullptr;
  /// Closed loop: the actuators (the differential-drive base, the steering ECU; null when the
  /// set has none), whose bytes host turns hold back for the controller.
  const Device* base = nullptr;
  const Device* steering = nullptr;
};

}  // namespace hil::harness

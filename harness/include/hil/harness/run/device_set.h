#pragma once
/// @file
/// The emulated devices of a scenario and the links they talk through, built from the scenario.
/// One place decides which device classes a scenario's sections create; the engine
/// drives whatever is here through the Device interface.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hil/firmware_emu/actuator/base_serial_device.h"
#include "hil/firmware_emu/actuator/isobus_steering_device.h"
#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/gnss/gnss_fix.h"
#include "hil/harness/core/machine_load.h"
#include "hil/harness/links/can_endpoint.h"
#include "hil/harness/links/serial_endpoint.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

struct DeviceSet {
  /// The greenhouse the range sensors cast against (section `greenhouse:`); declared before the
  /// devices, which point to it, so it outlives them.
  std::unique_ptr<world::GreenhouseWorld> world;
  std::vector<std::unique_ptr<Device>> devices;
  /// endpoints[i][p] is serial port p of devices[i]
  std::vector<std::vector<std::unique_ptr<SerialEndpoint>>> endpoints;
  /// Latest fix of each GNSS receiver (the raw-fix baseline reads these after each event).
  std::vector<std::function<const gnss::GnssFix*()>> fix_sources;
  /// {link name, path} for substitution into the estimator command ({ttyGPS} → RUN_DIR/ttyGPS).
  std::vector<std::pair<std::string, std::string>> links;
  /// The CAN bus (scenario section `can`); null when the scenario has none. Every device's
  /// DeviceOutput::can frames go out on it.
  std::unique_ptr<CanEndpoint> can;
  /// Closed loop: the differential-drive base (owned by `devices`), null otherwise.
  const actuator::BaseSerialDevice* base = nullptr;
  /// Closed loop on the isobus channel: the steering ECU (owned by `devices`), null otherwise.
  const actuator::IsobusSteeringDevice* steering = nullptr;
  /// Real time: the scheduling the run's threads really got ({"events" | "pacing", …}).
  std::vector<std::pair<std::string, link::ThreadSchedule>> threads;
  /// Real time: /proc/stat when the pacing started (schedule_error.json: what the machine gave).
  std::optional<CpuTicks> cpu_at_start;
};

/// Creates the devices, their ptys (symlinks and captures in `run_dir`) and the CAN bus.
/// @throws std::runtime_error when a link cannot be created.
DeviceSet BuildDevices(const Scenario& scenario, std::uint64_t seed, const std::string& run_dir);

}  // namespace hil::harness

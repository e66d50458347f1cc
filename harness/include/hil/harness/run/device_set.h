#pragma once
/// @file
/// The emulated devices of a scenario and the links they talk through, built from the scenario by
/// the device table's rows (devices/device_kind.h); the engine drives whatever is here through
/// the Device interface.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hil/harness/core/machine_load.h"
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// What the device table built (DeviceBuild), and how the run's threads were scheduled.
struct DeviceSet : DeviceBuild {
  /// Real time: the scheduling the run's threads really got ({"events" | "pacing", …}).
  std::vector<std::pair<std::string, link::ThreadSchedule>> threads;
  /// Real time: /proc/stat when the pacing started (schedule_error.json: what the machine gave).
  std::optional<CpuTicks> cpu_at_start;
};

/// Creates the CAN bus, then each row's devices in table order with their ptys (symlinks and
/// captures in `run_dir`).
/// @throws std::runtime_error when a link cannot be created.
DeviceSet BuildDevices(const Scenario& scenario, std::uint64_t seed, const std::string& run_dir);

}  // namespace hil::harness

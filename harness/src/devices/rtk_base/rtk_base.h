#pragma once
// Internal to the harness run stage: the RTK base (`rtk_base:`) for BuildDevices.
#include <cstdint>
#include <string>

#include "hil/harness/run/device_set.h"

namespace hil::harness {

/// Adds the scenario's RTK base (when present) on its pty (RUN_DIR/ttyRTCM by default).
void AddRtkBase(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceSet& set);

}  // namespace hil::harness

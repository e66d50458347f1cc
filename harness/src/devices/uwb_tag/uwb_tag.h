#pragma once
// Internal to the harness run stage: paper 003's devices (UWB tag, WT901C) for BuildDevices.
#include <cstdint>
#include <string>

#include "hil/harness/run/device_set.h"

namespace hil::harness {

/// Adds the scenario's `uwb:` and `wt901c:` devices (when present) with their links.
void AddPaper003Devices(const Scenario& s, std::uint64_t uwb_seed, std::uint64_t wit_seed,
                        const std::string& dir, DeviceSet& set);

}  // namespace hil::harness

#pragma once
// Internal to the devices stage: the lidar reader for its row.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the lidar section (optional; needs the greenhouse section, read before the table).
void ReadLidarSpec(const YamlReader& root, Scenario& s);

}  // namespace hil::harness

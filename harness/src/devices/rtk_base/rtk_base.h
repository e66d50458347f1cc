#pragma once
// Internal to the devices stage: the RTK base's reader for its row.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the rtk_base section (optional; rtk_base_spec.cc), after the origin and start_utc.
void ReadRtkBaseSpec(const YamlReader& root, Scenario& s);

}  // namespace hil::harness

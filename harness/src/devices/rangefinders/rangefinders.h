#pragma once
// Internal to the devices stage: the rangefinders reader for its row.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the rangefinders section (optional; needs the greenhouse section, read before the table).
void ReadRangefindersSpec(const YamlReader& root, Scenario& s);

}  // namespace hil::harness

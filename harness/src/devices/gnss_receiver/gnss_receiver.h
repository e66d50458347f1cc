#pragma once
// Internal to the devices stage: the GNSS receivers' reader for their row.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the `gnss` section (optional: without it, one receiver with the defaults) into s.gnss.
void ReadGnssReceiverSpec(const YamlReader& root, Scenario& s);

}  // namespace hil::harness

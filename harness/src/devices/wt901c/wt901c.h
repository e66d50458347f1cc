#pragma once
// Internal to the devices stage: the WT901C's reader for its row.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the `wt901c:` section (optional) into s.wt901c.
void ReadWt901cSpec(const YamlReader& root, Scenario& s);

}  // namespace hil::harness

#pragma once
// Internal to the devices stage: the ZED-F9P rover's reader for its row.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the zed_f9p section (optional; zed_f9p_spec.cc), after rtk_base.
void ReadZedF9pSpec(const YamlReader& root, Scenario& s);

}  // namespace hil::harness

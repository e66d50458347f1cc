#pragma once
// Internal to the harness report stage: navd.conf's [uwb] section for navd's UWB mode.
#include <ostream>
#include <string>

#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

/// Appends `[uwb]` (the tag's link, format, anchors, the frame's origin and time zero, and the
/// WT901C's link) for a scenario whose estimator.navd_mode is uwb. `gnss_device` locates the
/// run folder. @throws std::runtime_error when the scenario has no `uwb:` section.
void WriteNavdUwb(std::ostream& out, const Scenario& s, const std::string& gnss_device);

}  // namespace hil::harness

#pragma once
// Internal to the devices stage: the UWB tag's reader and navd.conf writer for its row.
#include <ostream>
#include <string>

#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the `uwb:` section (optional) into s.uwb.
void ReadUwbTagSpec(const YamlReader& root, Scenario& s);
/// At NavdConfSlot::kSections, for estimator.navd_mode uwb: `[uwb]` (the tag's link, format,
/// anchors, the frame's origin and time zero). @throws std::runtime_error when the scenario has no
/// `uwb:` section.
void WriteUwbTagNavd(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                     std::ostream& out);

}  // namespace hil::harness

#pragma once
// Internal to the devices stage: the GNSS receivers' reader for their row.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the `gnss` section (optional: without it, one receiver with the defaults) into s.gnss.
void ReadGnssReceiverSpec(const YamlReader& root, Scenario& s);
/// Reads the top-level `obstructions:` list into s.gnss.shading (gnss_rough_spec.cc).
void ReadSkyObstructions(const YamlReader& root, Scenario& s);
/// Reads `gnss.multipath` (signal thresholds) into s.gnss.shading.
void ReadGnssMultipath(const YamlReader& gnss, Scenario& s);
/// Reads `gnss.rtk` (the rough RTK; profile rtk only) into s.gnss.rtk_rough.
void ReadRtkRoughness(const YamlReader& gnss, Scenario& s);

}  // namespace hil::harness

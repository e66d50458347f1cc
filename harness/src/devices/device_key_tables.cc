// The device sections that have a table (scenario_keys.h), in the reference's order; each table is
// defined beside its reader in the kind's folder. A section missing here is listed by the
// reference among the sections without a table.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

extern const KeySection kUwbSection;  // uwb_tag/uwb_tag_spec.cc
extern const KeySection kNlosZoneSection;
extern const KeySection kWt901cSection;        // wt901c/wt901c_spec.cc
extern const KeySection kLidarSection;         // lidar/lidar_spec.cc
extern const KeySection kReflectivitySection;  // spec_readers.cc
extern const KeySection kRangefindersSection;  // rangefinders/rangefinders_spec.cc
extern const KeySection kRangefinderUnitSection;
extern const KeySection kZedF9pSection;  // zed_f9p/zed_f9p_spec.cc
extern const KeySection kZedF9pConfigSection;

namespace {

const KeySection* const kDeviceSections[] = {
    &kUwbSection,          &kNlosZoneSection,     &kWt901cSection,          &kLidarSection,
    &kReflectivitySection, &kRangefindersSection, &kRangefinderUnitSection, &kZedF9pSection,
    &kZedF9pConfigSection,
};

}  // namespace

std::span<const KeySection* const> DeviceKeySections() { return kDeviceSections; }

}  // namespace hil::harness

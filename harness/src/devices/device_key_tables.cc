// The device sections that have a table (scenario_keys.h), in the reference's order; each table is
// defined beside its reader in the kind's folder. A section missing here is listed by the
// reference among the sections without a table.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

extern const KeySection kGnssSection;  // gnss_receiver/gnss_rough_spec.cc
extern const KeySection kGnssErrorsSection;
extern const KeySection kGnssReceiverSection;
extern const KeySection kGnssFaultSection;
extern const KeySection kGnssMultipathSection;
extern const KeySection kGnssRtkSection;
extern const KeySection kObstacleSection;
extern const KeySection kMcuSection;  // mcu/mcu_spec.cc
extern const KeySection kMcuMagneticSection;
extern const KeySection kMcuVibrationSection;
extern const KeySection kMcuTemperatureSection;
extern const KeySection kMcuCanSection;
extern const KeySection kMcuFaultSection;
extern const KeySection kMcuRoughSection;  // mcu/mcu_rough_spec.cc
extern const KeySection kMcuRpmSection;
extern const KeySection kMcuEngineOrderSection;
extern const KeySection kMcuRideSection;
extern const KeySection kMcuMountSection;
extern const KeySection kMcuTemperaturePointSection;
extern const KeySection kMcuTimeTagSection;
extern const KeySection kMcuAccelSection;
extern const KeySection kMcuGyroSection;
extern const KeySection kRtkBaseSection;  // rtk_base/rtk_base_spec.cc
extern const KeySection kRtkBasePositionSection;
extern const KeySection kRtkBaseRadioSection;
extern const KeySection kRtkBaseOutageSection;
extern const KeySection kRtkBaseObservablesSection;
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
    &kGnssSection,
    &kGnssErrorsSection,
    &kGnssReceiverSection,
    &kGnssFaultSection,
    &kGnssMultipathSection,
    &kGnssRtkSection,
    &kObstacleSection,
    &kMcuSection,
    &kMcuMagneticSection,
    &kMcuVibrationSection,
    &kMcuTemperatureSection,
    &kMcuCanSection,
    &kMcuFaultSection,
    &kMcuRoughSection,
    &kMcuRpmSection,
    &kMcuEngineOrderSection,
    &kMcuRideSection,
    &kMcuMountSection,
    &kMcuTemperaturePointSection,
    &kMcuTimeTagSection,
    &kMcuAccelSection,
    &kMcuGyroSection,
    &kRtkBaseSection,
    &kRtkBasePositionSection,
    &kRtkBaseRadioSection,
    &kRtkBaseOutageSection,
    &kRtkBaseObservablesSection,
    &kUwbSection,
    &kNlosZoneSection,
    &kWt901cSection,
    &kLidarSection,
    &kReflectivitySection,
    &kRangefindersSection,
    &kRangefinderUnitSection,
    &kZedF9pSection,
    &kZedF9pConfigSection,
};

}  // namespace

std::span<const KeySection* const> DeviceKeySections() { return kDeviceSections; }

}  // namespace hil::harness

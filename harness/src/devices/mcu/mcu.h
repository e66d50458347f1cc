#pragma once
// Internal to the devices stage: the IMU board's MCU, its reader for its row.
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

/// Reads the mcu section (optional; mcu_spec.cc) into s.mcu: without it the scenario has no IMU
/// board. Without imu_rate_hz the IMU runs at 10 × the GNSS rate (the gnss row is read first).
void ReadMcuSpec(const YamlReader& root, Scenario& s);
/// Reads the mcu section's `rough` mapping (issue 41; mcu_rough_spec.cc) into `c`, over what
/// its `imu_profile` (if any) set.
void ReadMcuRough(const YamlReader& y, mcu::McuConfig& c);

}  // namespace hil::harness

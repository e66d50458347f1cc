#pragma once
/// @file
/// navd.conf `[imu]`: where the IMU comes from. `source = serial` (default): the device
/// `[input] imu_device` in `[input] imu_format` (mcu binary frames or the Razor v13 text lines).
/// `source = can`: the IMU microcontroller's J1939 frames (ARI, ACCS, SSI2, HIL_TIME_PULSE;
/// vectors/can/README.md) on the SocketCAN interface `can_interface`, from `source_address`.

#include <string>

#include "hil/estimator/navd/config_file.h"

namespace hil::estimator {

struct NavdImuConfig {
  std::string source = "serial";  ///< serial | can
  std::string can_interface;      ///< source = can: e.g. vcan0, can0
  int source_address = 0xE2;      ///< J1939 source address of the IMU (0 … 253); -1 = any source
  /// Razor text lines carry no time: they are stamped on arrival and mapped onto GPS time through
  /// the arrival of the GNSS fixes, each taken to arrive this long after its time of validity.
  double razor_gnss_latency_s = 0.1;
  int source_line = 0, can_interface_line = 0;  ///< where the keys were (for messages)

  bool from_can() const { return source == "can"; }
};

/// Reads one `[imu]` entry. @throws ConfigError naming file, line and key (unknown key included).
void ReadNavdImuKey(const ConfigFile& file, const ConfigEntry& entry, NavdImuConfig& imu);
/// Cross-checks `[imu]` against `[input]` once the file is read. @throws ConfigError.
void ValidateNavdImu(const ConfigFile& file, const NavdImuConfig& imu,
                     const std::string& imu_device, const std::string& imu_format);

}  // namespace hil::estimator

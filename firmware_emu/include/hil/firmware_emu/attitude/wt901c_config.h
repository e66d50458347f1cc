#pragma once
/// @file
/// Configuration of the WT901C emulator: power-on register values and the sensor's error model.
/// Error figures are assumptions of MEMS consumer grade (an MPU-9250-class gyro behind the WT901C's
/// fusion), not datasheet values: UNVERIFIED, see vectors/wt901c/README.md.

#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "hil/firmware_emu/sim_time.h"

namespace hil::wit {

struct Wt901cErrors {
  double gyro_turn_on_bias_sigma_dps = 0.05;  ///< per axis, per power-on (1σ)
  double gyro_noise_density_dps_rthz = 0.01;  ///< white rate noise, °/s/√Hz
  double gyro_bandwidth_hz = 21.0;            ///< BANDWIDTH register default (code 4)
  double accel_noise_sigma_g = 0.002;         ///< per output sample (1σ)
  double angle_noise_sigma_deg = 0.02;        ///< roll/pitch/yaw per output sample (1σ)
  double yaw_drift_sigma_dps = 0.005;         ///< residual yaw drift of the fusion (1σ)
  double mag_noise_sigma_counts = 2.0;        ///< per output sample (1σ)
};

struct Wt901cConfig {
  std::string name = "wt901c";
  std::uint16_t rrate_code = 0x06;  ///< RRATE: 10 Hz
  std::uint16_t baud_code = 0x02;   ///< BAUD: 9600
  std::uint16_t rsw = 0x001E;       ///< RSW: 0x51–0x54
  std::uint16_t version = 0x0000;   ///< reported in 0x53's D3 and register VERSION
  double temperature_c = 25.0;
  /// Earth field in ENU, in the sensor's raw magnetometer counts (UNVERIFIED unit, mG in BLE docs).
  Eigen::Vector3d mag_N_counts{0.0, 300.0, -400.0};
  /// The firmware ignores configuration writes until the KEY register holds 0xB588 (current
  /// firmware); false models firmware that accepts writes without unlocking.
  bool require_unlock = false;
  /// How long an unlock lasts (UNVERIFIED; the SDK writes within ~20 ms of unlocking).
  Duration unlock_window = std::chrono::seconds(10);
  /// Time from the host's command to the sensor's reply to a register read.
  Duration read_latency = std::chrono::milliseconds(2);
  Wt901cErrors errors;
};

/// Output rate (Hz) of an RRATE code; 0 for "single" (0x0C), "none" (0x0D) and unknown codes.
double RateHzOfCode(std::uint16_t rrate_code);
/// Line rate (bit/s) of a BAUD code; 0 for unknown codes.
int BaudOfCode(std::uint16_t baud_code);

}  // namespace hil::wit

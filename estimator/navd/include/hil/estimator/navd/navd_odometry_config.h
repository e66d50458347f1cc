#pragma once
/// @file
/// navd.conf `[odometry]`: navd's gyro + wheel-odometry mode (paper 001). When `device` is set
/// navd reads the IMU microcontroller on `[input] imu_device` and the base's encoder counts as
/// `$PHENC` sentences (odometry/encoder_sentence.h) on `device` (a FIFO or tty the controller
/// forwards the base's `e` replies into), fuses them in GyroOdometryFilter (the gyro bias fed
/// back) from a static alignment at the configured start pose, and writes the JSON lines and
/// `[output] nmea_device` (GGA, RMC, HDT) at `[output] rate_hz` (mode "gyro_odometry").
/// Keys (every one optional but `device`):
///   device; wheel_radius_m (0.1), track_m (0.5), counts_per_rev (1200): the base;
///   origin_lat_deg, origin_lon_deg, origin_height_m: the local plane's origin;
///   initial_e_m, initial_n_m (0), initial_heading_deg (0, true heading, clockwise from north):
///   the start pose of the drive axle's midpoint; align_s (2): the static alignment;
///   gyro_arw (1.5e-4 rad/√s), gyro_bias_rw (1e-5 rad/s/√s), init_gyro_bias_std (0.005 rad/s),
///   odo_yaw_std_rad (0.004 per interval), odo_distance_std_fraction (0.01),
///   odo_lateral_std_fraction (0.002): the filter's noise;
///   wait_s (0.5): at each solution after the first encoder sentence, how long navd waits for
///   the sentence that answers the solution before the previous one (wall time; a lockstep harness
///   delivers it within a turn; late ones are counted and used when they come).

#include <string>

#include "hil/estimator/navd/config_file.h"

namespace hil::estimator {

struct NavdOdometryConfig {
  std::string device;  ///< empty: not in odometry mode
  double wheel_radius_m = 0.1, track_m = 0.5;
  int counts_per_rev = 1200;
  double origin_lat_deg = 0, origin_lon_deg = 0, origin_height_m = 0;
  double initial_e_m = 0, initial_n_m = 0, initial_heading_deg = 0;
  double align_s = 2.0;
  double gyro_arw = 1.5e-4, gyro_bias_rw = 1e-5, init_gyro_bias_std = 0.005;
  double odo_yaw_std_rad = 0.004, odo_distance_std_fraction = 0.01,
         odo_lateral_std_fraction = 0.002;
  double wait_s = 0.5;
  bool enabled() const { return !device.empty(); }
};

/// Reads one `[odometry]` entry. @throws ConfigError naming file, line and key.
void ReadNavdOdometryKey(const ConfigFile& file, const ConfigEntry& entry,
                         NavdOdometryConfig& odometry);

}  // namespace hil::estimator

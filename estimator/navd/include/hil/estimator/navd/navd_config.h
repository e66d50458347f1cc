#pragma once
/// @file
/// The validated configuration of the navd daemon. Every key navd understands is listed in
/// NavdConfig with its section; unknown keys, wrong types and out-of-range values are errors that
/// name the file, line and key. The reference file is estimator/navd/navd.conf.example.

#include <string>

#include "hil/estimator/drivers/nmea_accuracy.h"
#include "hil/estimator/drivers/ubx_nav_pvt_sample.h"
#include "hil/estimator/navd/config_file.h"
#include "hil/estimator/navd/navd_gnss_receivers.h"
#include "hil/estimator/navd/navd_imu_config.h"
#include "hil/estimator/navd/navd_odometry_config.h"
#include "hil/estimator/navd/navd_uwb_config.h"
#include "hil/estimator/navigator.h"

namespace hil::estimator {

struct NavdConfig {
  // [input]
  std::string gnss_device;             ///< serial device of the GNSS receiver (NMEA); empty = none
  GnssReceiversConfig gnss_receivers;  ///< gnss_device_1 … and the antennas (multi_gnss)
  int gnss_baud = 9600;
  std::string gnss_protocol = "nmea";  ///< nmea (GGA + RMC) or ubx (NAV-POSLLH/VELNED/SOL)
  /// NMEA carries no accuracy estimate: a fix's horizontal 1σ per axis is HDOP × nmea_uere_m / √2
  /// (vertical twice that), or the configured RTK fixed/float 1σ (nmea_accuracy.h). UBX input uses
  /// the receiver's own hAcc/vAcc instead.
  double nmea_uere_m = 2.5;
  /// Configure the receiver at start-up with UBX CFG commands, each waiting for its ACK (and again
  /// after the port reopens): ubx → NAV-POSLLH/VELNED/SOL/TIMEGPS on, NMEA off; nmea → GGA and RMC
  /// only. Off by default (the receiver's saved configuration is used as it is).
  bool gnss_configure = false;
  double gnss_rate_hz = 0;  ///< with gnss_configure: CFG-RATE to this rate; 0 leaves the rate
  double nmea_rtk_fixed_std_m =
      0.0;  ///< [filter] 1σ per horizontal axis of RTK fixed fixes (0: UERE)
  double nmea_rtk_float_std_m =
      0.0;  ///< [filter] 1σ per horizontal axis of RTK float fixes (0: UERE)
  double nmea_velocity_std_mps = 0.2;  ///< [filter] 1σ per horizontal axis of the RMC velocity
  /// [input] gnss_nav_pvt: on an NMEA receiver's line, fuse the UBX NAV-PVT it also sends (its own
  /// hAcc/vAcc/sAcc and carrSoln) in place of its GGA/RMC; the NMEA epochs resume 2 s after the
  /// last NAV-PVT. UBX frames on the line are framed out of the NMEA stream either way.
  bool gnss_nav_pvt = true;
  /// [filter] ubx_acc_scale, ubx_pos_std_floor_m, ubx_vel_std_floor_mps, ubx_float_up_std_max_m
  /// (ubx_nav_pvt_sample.h)
  drivers::UbxPvtAccuracy ubx_pvt_accuracy;
  /// The NMEA accuracy settings together.
  NmeaAccuracy nmea_accuracy() const {
    return {nmea_uere_m, nmea_rtk_fixed_std_m, nmea_rtk_float_std_m, nmea_velocity_std_mps};
  }
  std::string imu_device;  ///< serial device of the IMU microcontroller; empty = none
  int imu_baud = 57600;
  std::string imu_format =
      "mcu";  ///< mcu (binary frame protocol v1) or razor_text (Razor v13 stock lines)
  /// Inputs to the filter in device-time order, held this long behind the newest IMU sample
  /// (input_merge.h); 0: as they are read.
  Nanoseconds merge_window{0};
  // [imu]: serial or CAN (navd_imu_config.h)
  NavdImuConfig imu;
  // [uwb]: navd's UWB mode when uwb.device is set (navd_uwb_config.h)
  NavdUwbConfig uwb;
  // [odometry]: navd's gyro + wheel-odometry mode when odometry.device is set
  NavdOdometryConfig odometry;
  // [time]
  int leap_seconds = 18;  ///< GPS − UTC until the receiver reports it
  // [filter]: mode and the estimator parameters (navigator.h, error_state_ekf.h)
  NavigatorParams nav;
  // [output]
  std::string json_path = "-";   ///< JSON lines: "-" for stdout, or a file path
  double output_rate_hz = 10.0;  ///< IMU modes: solution rate (GNSS-only modes: one per fix)
  std::string nmea_device;       ///< NMEA 0183 output (GGA, RMC, HDT) to this file/pty; empty = off
  std::string can_interface;     ///< NMEA 2000 output on this SocketCAN interface; empty = off
  std::string can_log;  ///< NMEA 2000 frames as `candump -l` lines to this file; empty = off
  int can_source_address = 0x80;  ///< NMEA 2000 source address
  double can_rate_hz = 10.0;      ///< 129025/127250/127257 rate (129026 at most 4 Hz, 129029 1 Hz)

  /// Every GNSS receiver's device, receiver 0 (gnss_device) first.
  std::vector<std::string> GnssDevices() const { return gnss_receivers.Devices(gnss_device); }
  /// NavMode shortcut.
  NavMode mode() const { return nav.mode; }
  /// Validates a parsed file. @throws ConfigError naming file, line and key.
  static NavdConfig FromFile(const ConfigFile& file);
};

}  // namespace hil::estimator

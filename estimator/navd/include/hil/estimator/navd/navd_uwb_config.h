#pragma once
/// @file
/// navd.conf `[uwb]`: navd's UWB mode (paper 003). When `device` is set navd reads the UWB tag
/// (HIL-UWB-TDOA0 frames solved in closed form, or the module's own NLink Tag_Frame0 positions),
/// corrects each position with Table 1's field (eq. 8), fuses it with the WT901C on
/// `attitude_device` (yaw rate and heading) in a planar filter, and writes the same JSON lines as
/// the other modes (mode "uwb"). Keys (every one optional but `device`):
///   device, baud (921600), format (tdoa | tag_frame0), anchors_m (x1, y1, … x4, y4: BS1–BS4 in
///   the ENU plane), correction (paper003 | none), origin_lat_deg, origin_lon_deg,
///   origin_height_m (the plane's origin), time_zero_unix_ns (UTC of the module's system_time 0),
///   attitude_device, attitude_baud (9600), attitude_rate_hz (10), attitude_yaw_offset_deg (ENU
///   yaw = sensor yaw + offset), position_std_m (0.06: the fix's white part), residual_std_m (0.05)
///   and residual_distance_m (2.0: the residual the correction leaves and the distance over which
///   it decorrelates), yaw_std_deg (1.0: the sensor yaw's white part), yaw_offset_std_deg (1.0)
///   and yaw_drift_std_dps (0.01: its offset and the offset's drift; uwb_planar_filter.h).

#include <array>
#include <cstdint>
#include <string>

#include "hil/estimator/navd/config_file.h"

namespace hil::estimator {

struct NavdUwbConfig {
  std::string device;  ///< empty: not in UWB mode
  int baud = 921600;
  std::string format = "tdoa";  ///< tdoa | tag_frame0
  std::array<double, 8> anchors_m{-10, -10, 10, -10, 10, 10, -10, 10};
  bool correction = true;  ///< apply paper 003's Table 1 correction (eq. 8)
  double origin_lat_deg = 0, origin_lon_deg = 0, origin_height_m = 0;
  std::int64_t time_zero_unix_ns = 0;
  std::string attitude_device;  ///< the WT901C; empty: no heading input
  int attitude_baud = 9600;
  double attitude_rate_hz = 10;
  double attitude_yaw_offset_deg = 0;
  double position_std_m = 0.06;
  double residual_std_m = 0.05;
  double residual_distance_m = 2.0;
  double yaw_offset_std_deg = 1.0;
  double yaw_drift_std_dps = 0.01;
  double yaw_std_deg = 1.0;
  bool enabled() const { return !device.empty(); }
};

/// Reads one `[uwb]` entry. @throws ConfigError naming file, line and key (unknown key included).
void ReadNavdUwbKey(const ConfigFile& file, const ConfigEntry& entry, NavdUwbConfig& uwb);

}  // namespace hil::estimator

#include "hil/estimator/navd/navd_config.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>

#include "hil/estimator/navd/serial_bauds.h"

namespace hil::estimator {
namespace {

int ToInt(const ConfigFile& f, const ConfigEntry& e, int lo, int hi) {
  int v = 0;
  const auto r = std::from_chars(e.value.data(), e.value.data() + e.value.size(), v);
  if (r.ec != std::errc() || r.ptr != e.value.data() + e.value.size()) {
    throw ConfigError(f.name(), e.line, FieldName(e), "expected an integer, got '" + e.value + "'");
  }
  if (v < lo || v > hi) {
    throw ConfigError(f.name(), e.line, FieldName(e),
                      "value " + e.value + " out of range [" + std::to_string(lo) + ", " +
                          std::to_string(hi) + "]");
  }
  return v;
}

// "true" or "false"; anything else is an error naming the file, line and key.
bool ToBool(const ConfigFile& f, const ConfigEntry& e) {
  if (e.value != "true" && e.value != "false")
    throw ConfigError(f.name(), e.line, FieldName(e), "expected true or false");
  return e.value == "true";
}

double ToDouble(const ConfigFile& f, const ConfigEntry& e, double lo, double hi) {
  char* end = nullptr;
  const double v = std::strtod(e.value.c_str(), &end);
  if (e.value.empty() || end != e.value.c_str() + e.value.size() || !std::isfinite(v)) {
    throw ConfigError(f.name(), e.line, FieldName(e), "expected a number, got '" + e.value + "'");
  }
  if (v < lo || v > hi) {
    std::ostringstream m;
    m << "value " << e.value << " out of range [" << lo << ", " << hi << "]";
    throw ConfigError(f.name(), e.line, FieldName(e), m.str());
  }
  return v;
}

// A baud rate navd can open a serial device at (serial_bauds.h); any other is an error.
int ToBaud(const ConfigFile& f, const ConfigEntry& e) {
  const int baud = ToInt(f, e, 1, 4'000'000);
  if (!hil::navd::SerialSpeed(baud)) {
    throw ConfigError(
        f.name(), e.line, FieldName(e),
        "unsupported baud rate " + e.value + " (supported: " + hil::navd::SerialBaudList() + ")");
  }
  return baud;
}

// A duration key given in seconds (the user-facing unit), in whole nanoseconds (truncated).
Nanoseconds TruncatedNs(double seconds) {
  return Nanoseconds{static_cast<std::int64_t>(seconds * 1e9)};
}

Eigen::Vector3d ToVector3(const ConfigFile& f, const ConfigEntry& e, double limit) {
  std::istringstream in(e.value);
  Eigen::Vector3d v;
  std::string part;
  int n = 0;
  while (std::getline(in, part, ',')) {
    ConfigEntry one = e;
    one.value = part;
    const auto b = one.value.find_first_not_of(" \t");
    const auto en = one.value.find_last_not_of(" \t");
    one.value = b == std::string::npos ? "" : one.value.substr(b, en - b + 1);
    if (n >= 3) break;
    v[n++] = ToDouble(f, one, -limit, limit);
  }
  if (n != 3 || std::getline(in, part, ',')) {
    throw ConfigError(f.name(), e.line, FieldName(e),
                      "expected three comma-separated numbers 'x, y, z', got '" + e.value + "'");
  }
  return v;
}

// An [input] key of navd itself (the receivers' own, gnss_device_N, excepted); false for another.
bool ReadInputKey(const ConfigFile& f, const ConfigEntry& e, NavdConfig& c) {
  if (e.section != "input") return false;
  const std::string& k = e.key;
  if (k == "gnss_device")
    c.gnss_device = e.value;
  else if (k == "gnss_baud")
    c.gnss_baud = ToBaud(f, e);
  else if (k == "gnss_protocol") {
    if (e.value != "nmea" && e.value != "ubx")
      throw ConfigError(f.name(), e.line, FieldName(e),
                        "unknown protocol '" + e.value + "' (known: nmea, ubx)");
    c.gnss_protocol = e.value;
  } else if (k == "gnss_configure") {
    c.gnss_configure = ToBool(f, e);
  } else if (k == "gnss_nav_pvt") {
    c.gnss_nav_pvt = ToBool(f, e);
  } else if (k == "gnss_rate_hz")
    c.gnss_rate_hz = ToDouble(f, e, 0.0, 10.0);
  else if (k == "merge_window_s")
    c.merge_window = TruncatedNs(ToDouble(f, e, 0.0, 10.0));
  else if (k == "imu_device")
    c.imu_device = e.value;
  else if (k == "imu_baud")
    c.imu_baud = ToBaud(f, e);
  else if (k == "imu_format") {
    if (e.value != "mcu" && e.value != "razor_text")
      throw ConfigError(f.name(), e.line, FieldName(e),
                        "unknown IMU format '" + e.value + "' (known: mcu, razor_text)");
    c.imu_format = e.value;
  } else
    return false;
  return true;
}

// A [filter] key of the error-state EKF's parameters; false for another.
bool ReadEkfKey(const ConfigFile& f, const ConfigEntry& e, EkfParams& ekf) {
  if (e.section != "filter") return false;
  const std::string& k = e.key;
  if (k == "lever_arm_m")
    ekf.lever_arm_B_m = ToVector3(f, e, 50.0);
  else if (k == "accel_noise")
    ekf.accel_noise_mps2_rthz = ToDouble(f, e, 1e-6, 10.0);
  else if (k == "gyro_noise")
    ekf.gyro_noise_radps_rthz = ToDouble(f, e, 1e-8, 1.0);
  else if (k == "gyro_scale_std")
    ekf.gyro_scale_std = ToDouble(f, e, 0.0, 0.1);
  else if (k == "gyro_scale_z_std")
    ekf.gyro_scale_z_std = ToDouble(f, e, 0.0, 0.1);
  else if (k == "gyro_scale_xy_std")
    ekf.gyro_scale_xy_std = ToDouble(f, e, 0.0, 0.1);
  else if (k == "gyro_scale_xy_rw_rthz")
    ekf.gyro_scale_xy_rw_rthz = ToDouble(f, e, 0.0, 0.01);
  else if (k == "imu_time_residual_std_s")
    ekf.imu_time_residual_std_s = ToDouble(f, e, 0.0, 0.1);
  else if (k == "accel_y_force_std")
    ekf.accel_y_force_std = ToDouble(f, e, 0.0, 0.1);
  else if (k == "gyro_z_coupling_std_deg")
    ekf.gyro_z_coupling_x_std_rad = ekf.gyro_z_coupling_y_std_rad =
        ToDouble(f, e, 0.0, 5.0) * std::numbers::pi / 180.0;
  else if (k == "gyro_z_coupling_x_std_deg")
    ekf.gyro_z_coupling_x_std_rad = ToDouble(f, e, 0.0, 5.0) * std::numbers::pi / 180.0;
  else if (k == "gyro_z_coupling_y_std_deg")
    ekf.gyro_z_coupling_y_std_rad = ToDouble(f, e, 0.0, 5.0) * std::numbers::pi / 180.0;
  else if (k == "accel_bias_rw")
    ekf.accel_bias_rw_mps3_rthz = ToDouble(f, e, 0.0, 1.0);
  else if (k == "gyro_bias_rw")
    ekf.gyro_bias_rw_radps2_rthz = ToDouble(f, e, 0.0, 0.1);
  else if (k == "init_accel_bias_std")
    ekf.init_accel_bias_std_mps2 = ToDouble(f, e, 0.0, 10.0);
  else if (k == "init_gyro_bias_std")
    ekf.init_gyro_bias_std_radps = ToDouble(f, e, 0.0, 1.0);
  else if (k == "gnss_error_tau_s")
    ekf.gnss_error_tau_s = ToDouble(f, e, 0.0, 3600.0);
  else if (k == "gnss_error_std_m")
    ekf.gnss_error_std_m = ToDouble(f, e, 0.0, 100.0);
  else if (k == "gnss_error_vertical_std_m")
    ekf.gnss_error_vertical_std_m = ToDouble(f, e, 0.0, 100.0);
  else if (k == "gnss_error_vdop_ref")
    ekf.gnss_error_vdop_ref = ToDouble(f, e, 0.0, 100.0);
  else if (k == "gnss_float_error_tau_s")
    ekf.gnss_float_error_tau_s = ToDouble(f, e, 0.0, 3600.0);
  else if (k == "gnss_float_error_std_m")
    ekf.gnss_float_error_std_m = ToDouble(f, e, 0.0, 100.0);
  else if (k == "nhc_std_mps")
    ekf.nhc_std_mps = ToDouble(f, e, 0.0, 10.0);
  else if (k == "speed_rw")
    ekf.speed_rw_mps_rthz = ToDouble(f, e, 0.0, 10.0);
  else if (k == "speed_dev_std_mps")
    ekf.speed_dev_std_mps = ToDouble(f, e, 0.001, 10.0);
  else if (k == "speed_dev_tau_s")
    ekf.speed_dev_tau_s = ToDouble(f, e, 0.0, 3600.0);
  else if (k == "vehicle_lowpass_tau_s")
    ekf.vehicle_lowpass_tau_s = ToDouble(f, e, 0.0, 10.0);
  else if (k == "gate_sigma")
    ekf.gate_sigma = ToDouble(f, e, 1.0, 1000.0);
  else if (k == "mount_pitch_std_deg")
    ekf.mount_pitch_std_rad = ToDouble(f, e, 0.0, 10.0) * std::numbers::pi / 180.0;
  else if (k == "mount_yaw_std_deg")
    ekf.mount_yaw_std_rad = ToDouble(f, e, 0.0, 10.0) * std::numbers::pi / 180.0;
  else if (k == "mount_angle_estimation") {
    ekf.estimate_mount_angles = ToBool(f, e);
  } else if (k == "gnss_float_error_from_receiver") {
    ekf.gnss_float_error_from_receiver = ToBool(f, e);
  } else
    return false;
  return true;
}

// The other [filter] keys: the mode, the NMEA accuracies and the navigator's timing; `mode_line`
// and `latency_line` note where mode and gnss_max_latency_s stand. False for another key.
bool ReadFilterKey(const ConfigFile& f, const ConfigEntry& e, NavdConfig& c, int& mode_line,
                   int& latency_line) {
  if (e.section != "filter") return false;
  const std::string& k = e.key;
  if (k == "nmea_uere_m")
    c.nmea_uere_m = ToDouble(f, e, 0.005, 100.0);
  else if (k == "nmea_rtk_fixed_std_m")
    c.nmea_rtk_fixed_std_m = ToDouble(f, e, 0.001, 10.0);
  else if (k == "nmea_rtk_float_std_m")
    c.nmea_rtk_float_std_m = ToDouble(f, e, 0.001, 100.0);
  else if (k == "nmea_velocity_std_mps")
    c.nmea_velocity_std_mps = ToDouble(f, e, 0.001, 10.0);
  else if (k == "ubx_acc_scale")
    c.ubx_pvt_accuracy.scale = ToDouble(f, e, 0.1, 100.0);
  else if (k == "ubx_pos_std_floor_m")
    c.ubx_pvt_accuracy.pos_floor_m = ToDouble(f, e, 0.0, 100.0);
  else if (k == "ubx_vel_std_floor_mps")
    c.ubx_pvt_accuracy.vel_floor_mps = ToDouble(f, e, 0.0, 10.0);
  else if (k == "ubx_float_up_std_max_m")
    c.ubx_pvt_accuracy.float_up_max_std_m = ToDouble(f, e, 0.001, 100.0);
  else if (k == "mode") {
    const auto m = NavModeFromName(e.value.c_str());
    if (!m)
      throw ConfigError(
          f.name(), e.line, FieldName(e),
          "unknown mode '" + e.value + "' (known: ekf, planar2d, gnss_only, imu_only, multi_gnss)");
    c.nav.mode = *m;
    mode_line = e.line;
  } else if (k == "fusion_horizon_s")
    c.nav.fusion_horizon = TruncatedNs(ToDouble(f, e, 0.0, 2.0));
  else if (k == "gnss_max_latency_s") {
    c.nav.gnss_max_latency = TruncatedNs(ToDouble(f, e, 0.0, 5.0));
    latency_line = e.line;
  } else if (k == "adaptive" || k == "fade_to_fixes" || k == "stationary_detection" ||
             k == "imu_lag_estimation" || k == "rtk_fix_check" || k == "imu_noise_check" ||
             k == "imu_usability_check" || k == "gnss_velocity_noise" || k == "gate_median_nis" ||
             k == "nhc_noise_check" || k == "fade_gap_noise") {
    const bool on = ToBool(f, e);
    (k == "adaptive"               ? c.nav.robust.adaptive
     : k == "fade_to_fixes"        ? c.nav.robust.fade_to_fixes
     : k == "stationary_detection" ? c.nav.stationary.enabled
     : k == "rtk_fix_check"        ? c.nav.rtk_fix.enabled
     : k == "imu_noise_check"      ? c.nav.imu_noise.enabled
     : k == "imu_usability_check"  ? c.nav.imu_usability.enabled
     : k == "gnss_velocity_noise"  ? c.nav.gnss_vel_noise.enabled
     : k == "gate_median_nis"      ? c.nav.robust.gate_follows_median_nis
     : k == "nhc_noise_check"      ? c.nav.nhc_noise.enabled
     : k == "fade_gap_noise"       ? c.nav.robust.fade_gap_noise
                                   : c.nav.imu_lag.enabled) = on;
  } else if (k == "imu_usability_window_s") {
    c.nav.imu_usability.window_s = ToDouble(f, e, 2.0, 600.0);
  } else if (k == "imu_usability_windows") {
    c.nav.imu_usability.windows = ToInt(f, e, 3, 16);
    c.nav.imu_usability.leave_tests = c.nav.imu_usability.windows;
  } else if (k == "fallback_yaw_rate_rw") {
    c.nav.fallback_vehicle.yaw_rate_rw_radps_rthz = ToDouble(f, e, 1e-6, 10.0);
  } else if (k == "fallback_position_rw") {
    c.nav.fallback_vehicle.position_rw_m_rthz = ToDouble(f, e, 1e-6, 10.0);
  } else if (k == "accel_scatter_tau_s") {
    c.nav.accel_scatter_tau_s = ToDouble(f, e, 0.0, 600.0);
  } else if (k == "accel_scatter_max_rate_hz") {
    c.nav.accel_scatter_max_rate_hz = ToDouble(f, e, 0.0, 10000.0);
  } else if (k == "vibration_tau_s") {
    c.nav.vibration_tau_s = ToDouble(f, e, 0.0, 10.0);
  } else if (k == "zupt_std_mps") {
    c.nav.stationary.zupt_std_mps = ToDouble(f, e, 0.001, 1.0);
  } else if (k == "use_gnss_velocity") {
    c.nav.use_gnss_velocity = ToBool(f, e);
  } else if (k == "fix_velocity_ripple") {
    c.nav.fix_velocity_ripple = ToBool(f, e);
  } else
    return false;
  return true;
}

// An [output] key; false for another.
bool ReadOutputKey(const ConfigFile& f, const ConfigEntry& e, NavdConfig& c) {
  if (e.section != "output") return false;
  const std::string& k = e.key;
  if (k == "json")
    c.json_path = e.value;
  else if (k == "rate_hz")
    c.output_rate_hz = ToDouble(f, e, 0.1, 1000.0);
  else if (k == "nmea_device")
    c.nmea_device = e.value;
  else if (k == "can_interface")
    c.can_interface = e.value;
  else if (k == "can_log")
    c.can_log = e.value;
  else if (k == "can_source_address")
    c.can_source_address = ToInt(f, e, 0, 251);
  else if (k == "can_rate_hz")
    c.can_rate_hz = ToDouble(f, e, 0.1, 100.0);
  else
    return false;
  return true;
}

// The rules that join keys, once the whole file is read.
void CheckAcrossKeys(const ConfigFile& f, NavdConfig& c, int mode_line, int latency_line) {
  const bool needs_imu = UsesImu(c.nav.mode);
  ValidateNavdImu(f, c.imu, c.imu_device, c.imu_format);
  if (needs_imu && c.imu_device.empty() && !c.imu.from_can()) {
    throw ConfigError(f.name(), mode_line, "[filter] mode",
                      std::string("mode ") + NavModeName(c.nav.mode) + " needs [input] imu_device");
  }
  c.gnss_receivers.Validate(f, c.gnss_device, mode_line, c.nav);
  if (c.nav.ekf.gnss_error_tau_s > 0 && c.nav.ekf.gnss_error_std_m <= 0) {
    throw ConfigError(f.name(), 0, "[filter] gnss_error_std_m",
                      "must be > 0 when gnss_error_tau_s is set");
  }
  if ((c.nav.ekf.gnss_float_error_tau_s > 0) != (c.nav.ekf.gnss_float_error_std_m > 0) ||
      (c.nav.ekf.gnss_float_error_tau_s > 0 && !(c.nav.ekf.gnss_error_tau_s > 0))) {
    throw ConfigError(f.name(), 0, "[filter] gnss_float_error_tau_s",
                      "gnss_float_error_tau_s and gnss_float_error_std_m go together, and need "
                      "gnss_error_tau_s > 0");
  }
  if (latency_line > 0 && c.nav.gnss_max_latency < c.nav.fusion_horizon) {
    throw ConfigError(
        f.name(), latency_line, "[filter] gnss_max_latency_s",
        "must be at least fusion_horizon_s (the filter never runs closer than the horizon)");
  }
}

}  // namespace

NavdConfig NavdConfig::FromFile(const ConfigFile& f) {
  NavdConfig c;
  c.nav.mode = NavMode::kGnssOnly;  // the default without an IMU
  int mode_line = 0, latency_line = 0;
  for (const ConfigEntry& e : f.entries()) {
    if (ReadInputKey(f, e, c) || ReadEkfKey(f, e, c.nav.ekf) ||
        ReadFilterKey(f, e, c, mode_line, latency_line) || ReadOutputKey(f, e, c))
      continue;
    if (e.section == "time" && e.key == "leap_seconds")
      c.leap_seconds = ToInt(f, e, 0, 60);
    else if (e.section == "imu")
      ReadNavdImuKey(f, e, c.imu);
    else if (e.section == "uwb")
      ReadNavdUwbKey(f, e, c.uwb);
    else if (e.section == "odometry")
      ReadNavdOdometryKey(f, e, c.odometry);
    else if (c.gnss_receivers.Read(f, e))
      continue;  // gnss_device_N, antenna_N_m
    else
      throw ConfigError(f.name(), e.line, FieldName(e), "unknown key");
  }
  CheckAcrossKeys(f, c, mode_line, latency_line);
  return c;
}

}  // namespace hil::estimator

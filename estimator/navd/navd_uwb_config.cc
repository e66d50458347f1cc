#include "hil/estimator/navd/navd_uwb_config.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "hil/estimator/navd/serial_bauds.h"

namespace hil::estimator {
namespace {

double Number(const ConfigFile& f, const ConfigEntry& e, const std::string& text, double lo,
              double hi) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
    FailAt(f, e, "expected a number, got '" + text + "'");
  if (v < lo || v > hi) {
    std::ostringstream m;
    m << "value " << text << " out of range [" << lo << ", " << hi << "]";
    FailAt(f, e, m.str());
  }
  return v;
}

int Baud(const ConfigFile& f, const ConfigEntry& e) {
  const double v = Number(f, e, e.value, 1, 4'000'000);
  const int baud = static_cast<int>(v);
  if (baud != v || !hil::navd::SerialSpeed(baud))
    FailAt(
        f, e,
        "unsupported baud rate " + e.value + " (supported: " + hil::navd::SerialBaudList() + ")");
  return baud;
}

std::array<double, 8> Anchors(const ConfigFile& f, const ConfigEntry& e) {
  std::array<double, 8> a{};
  std::istringstream in(e.value);
  std::string part;
  std::size_t n = 0;
  while (std::getline(in, part, ',')) {
    const auto b = part.find_first_not_of(" \t"), en = part.find_last_not_of(" \t");
    part = b == std::string::npos ? "" : part.substr(b, en - b + 1);
    if (n == a.size()) FailAt(f, e, "expected eight numbers x1, y1, … x4, y4 (m)");
    a[n++] = Number(f, e, part, -1e4, 1e4);
  }
  if (n != a.size()) FailAt(f, e, "expected eight numbers x1, y1, … x4, y4 (m)");
  return a;
}

}  // namespace

void ReadNavdUwbKey(const ConfigFile& f, const ConfigEntry& e, NavdUwbConfig& u) {
  const std::string& k = e.key;
  if (k == "device" || k == "attitude_device") {
    if (e.value.empty()) FailAt(f, e, "expected a device path");
    (k == "device" ? u.device : u.attitude_device) = e.value;
  } else if (k == "baud" || k == "attitude_baud") {
    (k == "baud" ? u.baud : u.attitude_baud) = Baud(f, e);
  } else if (k == "format") {
    if (e.value != "tdoa" && e.value != "tag_frame0")
      FailAt(f, e, "unknown format '" + e.value + "' (known: tdoa, tag_frame0)");
    u.format = e.value;
  } else if (k == "correction") {
    if (e.value != "paper003" && e.value != "none")
      FailAt(f, e, "unknown correction '" + e.value + "' (known: paper003, none)");
    u.correction = e.value == "paper003";
  } else if (k == "anchors_m") {
    u.anchors_m = Anchors(f, e);
  } else if (k == "origin_lat_deg") {
    u.origin_lat_deg = Number(f, e, e.value, -90, 90);
  } else if (k == "origin_lon_deg") {
    u.origin_lon_deg = Number(f, e, e.value, -180, 180);
  } else if (k == "origin_height_m") {
    u.origin_height_m = Number(f, e, e.value, -1000, 10000);
  } else if (k == "time_zero_unix_ns") {
    std::int64_t v = 0;
    const auto r = std::from_chars(e.value.data(), e.value.data() + e.value.size(), v);
    if (r.ec != std::errc() || r.ptr != e.value.data() + e.value.size() || v < 0)
      FailAt(f, e, "expected non-negative integer nanoseconds, got '" + e.value + "'");
    u.time_zero_unix_ns = v;
  } else if (k == "attitude_rate_hz") {
    u.attitude_rate_hz = Number(f, e, e.value, 0.1, 1000);
  } else if (k == "attitude_yaw_offset_deg") {
    u.attitude_yaw_offset_deg = Number(f, e, e.value, -360, 360);
  } else if (k == "position_std_m") {
    u.position_std_m = Number(f, e, e.value, 0.001, 100);
  } else if (k == "residual_std_m") {
    u.residual_std_m = Number(f, e, e.value, 0, 100);
  } else if (k == "residual_distance_m") {
    u.residual_distance_m = Number(f, e, e.value, 0.01, 10000);
  } else if (k == "yaw_offset_std_deg") {
    u.yaw_offset_std_deg = Number(f, e, e.value, 0, 180);
  } else if (k == "yaw_drift_std_dps") {
    u.yaw_drift_std_dps = Number(f, e, e.value, 0, 10);
  } else if (k == "yaw_std_deg") {
    u.yaw_std_deg = Number(f, e, e.value, 0.001, 180);
  } else {
    FailAt(f, e, "unknown key");
  }
}

}  // namespace hil::estimator

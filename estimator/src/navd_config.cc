#include "hil/estimator/navd_config.h"

#include <charconv>

namespace hil::estimator {
namespace {

int ToInt(const ConfigFile& f, const ConfigEntry& e, int lo, int hi) {
  int v = 0;
  const auto r = std::from_chars(e.value.data(), e.value.data() + e.value.size(), v);
  if (r.ec != std::errc() || r.ptr != e.value.data() + e.value.size()) {
    throw ConfigError(f.name(), e.line, "[" + e.section + "] " + e.key, "expected an integer, got '" + e.value + "'");
  }
  if (v < lo || v > hi) {
    throw ConfigError(f.name(), e.line, "[" + e.section + "] " + e.key,
                      "value " + e.value + " out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return v;
}

}  // namespace

NavdConfig NavdConfig::FromFile(const ConfigFile& f) {
  NavdConfig c;
  for (const ConfigEntry& e : f.entries()) {
    const std::string field = "[" + e.section + "] " + e.key;
    if (e.section == "input" && e.key == "gnss_device") {
      c.gnss_device = e.value;
    } else if (e.section == "input" && e.key == "gnss_baud") {
      c.gnss_baud = ToInt(f, e, 1200, 921600);
    } else if (e.section == "time" && e.key == "leap_seconds") {
      c.leap_seconds = ToInt(f, e, 0, 60);
    } else if (e.section == "filter" && e.key == "mode") {
      const auto m = NavModeFromName(e.value.c_str());
      if (!m) throw ConfigError(f.name(), e.line, field, "unknown mode '" + e.value + "' (known: ekf, planar2d, gnss_only, imu_only, multi_gnss)");
      c.mode = *m;
    } else if (e.section == "output" && e.key == "json") {
      c.json_path = e.value;
    } else {
      throw ConfigError(f.name(), e.line, field, "unknown key");
    }
  }
  return c;
}

}  // namespace hil::estimator

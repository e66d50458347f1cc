#include "hil/estimator/navd/navd_imu_config.h"

#include <cmath>
#include <cstdlib>

namespace hil::estimator {
void ReadNavdImuKey(const ConfigFile& f, const ConfigEntry& e, NavdImuConfig& imu) {
  const auto fail = [&](const std::string& m) {
    throw ConfigError(f.name(), e.line, FieldName(e), m);
  };
  if (e.key == "source") {
    if (e.value != "serial" && e.value != "can")
      fail("unknown IMU source '" + e.value + "' (known: serial, can)");
    imu.source = e.value;
    imu.source_line = e.line;
  } else if (e.key == "can_interface") {
    if (e.value.empty() || e.value.size() > 15 ||
        e.value.find_first_of("/ \t") != std::string::npos)
      fail("must be a network interface name such as vcan0 or can0, got '" + e.value + "'");
    imu.can_interface = e.value;
    imu.can_interface_line = e.line;
  } else if (e.key == "source_address") {
    if (e.value == "any") {
      imu.source_address = -1;
      return;
    }
    char* end = nullptr;
    const long v = std::strtol(e.value.c_str(), &end, 0);  // decimal or 0x hex
    if (e.value.empty() || end != e.value.c_str() + e.value.size())
      fail("expected a J1939 source address (0 … 253, decimal or 0x hex) or 'any', got '" +
           e.value + "'");
    if (v < 0 || v > 253) fail("source address " + e.value + " out of range [0, 253]");
    imu.source_address = static_cast<int>(v);
  } else if (e.key == "razor_gnss_latency_s") {
    char* end = nullptr;
    const double v = std::strtod(e.value.c_str(), &end);
    if (e.value.empty() || end != e.value.c_str() + e.value.size() || !std::isfinite(v))
      fail("expected a number, got '" + e.value + "'");
    if (v < 0 || v > 2) fail("value " + e.value + " out of range [0, 2]");
    imu.razor_gnss_latency_s = v;
  } else {
    fail("unknown key");
  }
}

void ValidateNavdImu(const ConfigFile& f, const NavdImuConfig& imu, const std::string& imu_device,
                     const std::string& imu_format) {
  if (imu.from_can() && imu.can_interface.empty())
    throw ConfigError(f.name(), imu.source_line, "[imu] source",
                      "source = can needs [imu] can_interface (e.g. vcan0)");
  if (imu.from_can() && !imu_device.empty())
    throw ConfigError(
        f.name(), imu.source_line, "[imu] source",
        "source = can reads the IMU from [imu] can_interface; remove [input] imu_device");
  if (!imu.from_can() && !imu.can_interface.empty())
    throw ConfigError(f.name(), imu.can_interface_line, "[imu] can_interface",
                      "is only read with [imu] source = can");
  (void)imu_format;
}

}  // namespace hil::estimator

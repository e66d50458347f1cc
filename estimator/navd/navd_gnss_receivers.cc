#include "hil/estimator/navd/navd_gnss_receivers.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace hil::estimator {
namespace {

// The N of `<prefix>N<suffix>`, or -1 when the key does not have that form.
int IndexOf(const std::string& key, const std::string& prefix, const std::string& suffix) {
  if (key.size() <= prefix.size() + suffix.size() || key.compare(0, prefix.size(), prefix) != 0 ||
      key.compare(key.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return -1;
  }
  const std::string digits = key.substr(prefix.size(), key.size() - prefix.size() - suffix.size());
  int n = -1;
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (r.ec != std::errc() || r.ptr != digits.data() + digits.size() || n < 0 || n > 99) return -1;
  return n;
}

Eigen::Vector3d ParseVector(const ConfigFile& f, const ConfigEntry& e) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  std::size_t pos = 0;
  int n = 0;
  const std::string& s = e.value;
  while (pos <= s.size()) {
    const std::size_t comma = s.find(',', pos);
    std::string part = s.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    const auto b = part.find_first_not_of(" \t"), en = part.find_last_not_of(" \t");
    part = b == std::string::npos ? "" : part.substr(b, en - b + 1);
    char* end = nullptr;
    const double x = std::strtod(part.c_str(), &end);
    if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(x) ||
        std::abs(x) > 100.0 || n >= 3) {
      throw ConfigError(
          f.name(), e.line, FieldName(e),
          "expected three comma-separated numbers 'x, y, z' (metres, |value| <= 100), got '" + s +
              "'");
    }
    v[n++] = x;
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  if (n != 3) {
    throw ConfigError(f.name(), e.line, FieldName(e),
                      "expected three comma-separated numbers 'x, y, z', got '" + s + "'");
  }
  return v;
}

}  // namespace

bool GnssReceiversConfig::Read(const ConfigFile& f, const ConfigEntry& e) {
  const int max_index = kMaxGnssReceivers - 1;
  if (e.section == "input") {
    const int i = IndexOf(e.key, "gnss_device_", "");
    if (i < 0) return false;
    if (i < 1 || i > max_index) {
      throw ConfigError(f.name(), e.line, FieldName(e),
                        "receiver index out of range [1, " + std::to_string(max_index) +
                            "] (gnss_device is receiver 0; navd reads at most " +
                            std::to_string(kMaxGnssReceivers) + " receivers)");
    }
    const auto k = static_cast<std::size_t>(i - 1);
    if (extra_devices.size() <= k) extra_devices.resize(k + 1), extra_device_lines.resize(k + 1, 0);
    if (extra_device_lines[k] != 0) {
      throw ConfigError(
          f.name(), e.line, FieldName(e),
          "given twice (first on line " + std::to_string(extra_device_lines[k]) + ")");
    }
    if (e.value.empty())
      throw ConfigError(f.name(), e.line, FieldName(e), "expected a device path");
    extra_devices[k] = e.value;
    extra_device_lines[k] = e.line;
    return true;
  }
  if (e.section == "filter") {
    const int i = IndexOf(e.key, "antenna_", "_m");
    if (i < 0) return false;
    if (i > max_index) {
      throw ConfigError(f.name(), e.line, FieldName(e),
                        "receiver index out of range [0, " + std::to_string(max_index) + "]");
    }
    const auto k = static_cast<std::size_t>(i);
    if (antenna_B_m.size() <= k) antenna_B_m.resize(k + 1), antenna_lines.resize(k + 1, 0);
    if (antenna_lines[k] != 0) {
      throw ConfigError(f.name(), e.line, FieldName(e),
                        "given twice (first on line " + std::to_string(antenna_lines[k]) + ")");
    }
    antenna_B_m[k] = ParseVector(f, e);
    antenna_lines[k] = e.line;
    return true;
  }
  return false;
}

std::vector<std::string> GnssReceiversConfig::Devices(const std::string& gnss_device) const {
  if (gnss_device.empty()) return {};
  std::vector<std::string> out{gnss_device};
  out.insert(out.end(), extra_devices.begin(), extra_devices.end());
  return out;
}

void GnssReceiversConfig::Validate(const ConfigFile& f, const std::string& gnss_device,
                                   int mode_line, NavigatorParams& nav) const {
  // receivers 1 … n−1 without gaps, after receiver 0, on distinct devices
  for (std::size_t k = 0; k < extra_devices.size(); ++k) {
    const std::string key = "[input] gnss_device_" + std::to_string(k + 1);
    if (extra_device_lines[k] == 0) {
      const std::size_t last = extra_devices.size() - 1;
      throw ConfigError(f.name(), extra_device_lines[last],
                        "[input] gnss_device_" + std::to_string(last + 1),
                        "receivers are numbered without gaps: " + key + " is missing");
    }
    if (gnss_device.empty()) {
      throw ConfigError(f.name(), extra_device_lines[k], key,
                        "needs [input] gnss_device (receiver 0)");
    }
    if (extra_devices[k] == gnss_device) {
      throw ConfigError(f.name(), extra_device_lines[k], key,
                        "'" + extra_devices[k] + "' is already [input] gnss_device");
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (extra_devices[j] == extra_devices[k]) {
        throw ConfigError(
            f.name(), extra_device_lines[k], key,
            "'" + extra_devices[k] + "' is already [input] gnss_device_" + std::to_string(j + 1));
      }
    }
  }
  const std::size_t receivers = gnss_device.empty() ? 0 : 1 + extra_devices.size();
  for (std::size_t k = 0; k < antenna_B_m.size(); ++k) {
    if (antenna_B_m[k] && k >= receivers) {
      throw ConfigError(f.name(), antenna_lines[k], "[filter] antenna_" + std::to_string(k) + "_m",
                        "there is no receiver " + std::to_string(k) + " (" +
                            std::to_string(receivers) + " configured)");
    }
  }
  if (nav.mode != NavMode::kMultiGnss) {
    if (!extra_devices.empty()) {
      throw ConfigError(f.name(), extra_device_lines[0], "[input] gnss_device_1",
                        std::string("mode ") + NavModeName(nav.mode) +
                            " reads one receiver; several need [filter] mode = multi_gnss");
    }
    return;
  }
  if (receivers < 2) {
    throw ConfigError(
        f.name(), mode_line, "[filter] mode",
        "mode multi_gnss needs at least two receivers ([input] gnss_device and gnss_device_1 …)");
  }
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < receivers; ++k) {
    if (k >= antenna_B_m.size() || !antenna_B_m[k]) {
      throw ConfigError(f.name(), mode_line, "[filter] antenna_" + std::to_string(k) + "_m",
                        "mode multi_gnss needs the antenna of every receiver (body frame x "
                        "forward, y left, z up, metres)");
    }
    centre += antenna_B_m[k]->head<2>() / static_cast<double>(receivers);
  }
  double spread = 0;
  for (std::size_t k = 0; k < receivers; ++k)
    spread = std::max(spread, (antenna_B_m[k]->head<2>() - centre).norm());
  if (spread < 0.05) {
    throw ConfigError(
        f.name(), antenna_lines[0], "[filter] antenna_0_m",
        "the antennas must lie at least 5 cm from their centre horizontally to give a heading");
  }
  nav.multi_antenna_count = static_cast<int>(receivers);
  nav.multi_antenna_B_m.setZero();
  for (std::size_t k = 0; k < receivers; ++k)
    nav.multi_antenna_B_m.col(static_cast<Eigen::Index>(k)) = *antenna_B_m[k];
}

}  // namespace hil::estimator

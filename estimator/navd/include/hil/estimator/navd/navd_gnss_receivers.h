#pragma once
/// @file
/// navd's GNSS receivers beyond the first: `[input] gnss_device_1 … gnss_device_3` (the first is
/// `[input] gnss_device`) and their antennas `[filter] antenna_0_m … antenna_3_m` (body frame FLU,
/// metres; antenna_0_m belongs to gnss_device). Several receivers are read in `[filter] mode =
/// multi_gnss` only, which combines one fix of every receiver per epoch into the centre position
/// and the heading (seed 000: three NEO-5M on a 3 m circle). All receivers share gnss_baud and
/// gnss_protocol. Validation errors name the file, the line and the key.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/estimator/navd/config_file.h"
#include "hil/estimator/navigator.h"

namespace hil::estimator {

/// Receivers navd reads at most (the multi-receiver mode's limit).
inline constexpr int kMaxGnssReceivers = kMaxGnssAntennas;

struct GnssReceiversConfig {
  /// Devices of receivers 1 … n−1 (receiver 0 is [input] gnss_device); empty string = not given.
  std::vector<std::string> extra_devices;
  std::vector<int> extra_device_lines;
  /// Antenna of each receiver index (body FLU, m), when given.
  std::vector<std::optional<Eigen::Vector3d>> antenna_B_m;
  std::vector<int> antenna_lines;

  /// Consumes `[input] gnss_device_N` and `[filter] antenna_N_m`; returns false for other keys.
  /// @throws ConfigError on a bad index, a value that is not three numbers, or a key given twice.
  bool Read(const ConfigFile& file, const ConfigEntry& entry);
  /// After every key is read: checks the receivers against the mode and fills the navigator's
  /// antenna geometry. `mode_line` is the line of [filter] mode (0 when absent).
  /// @throws ConfigError naming the offending key.
  void Validate(const ConfigFile& file, const std::string& gnss_device, int mode_line,
                NavigatorParams& nav) const;
  /// Every receiver's device in index order (gnss_device first); empty when gnss_device is empty.
  std::vector<std::string> Devices(const std::string& gnss_device) const;
};

}  // namespace hil::estimator

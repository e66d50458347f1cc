#pragma once
/// @file
/// The validated configuration of the navd daemon. Every key navd understands is listed in
/// NavdConfig with its section; unknown keys, wrong types and out-of-range values are errors that
/// name the file, line and key. The reference file is estimator/navd/navd.conf.example.

#include <string>

#include "hil/estimator/config_file.h"
#include "hil/estimator/navigator.h"

namespace hil::estimator {

struct NavdConfig {
  // [input]
  std::string gnss_device;       ///< serial device of the GNSS receiver (NMEA/UBX); empty = none
  int gnss_baud = 9600;
  // [time]
  int leap_seconds = 18;         ///< GPS − UTC until the receiver reports it
  // [filter]
  NavMode mode = NavMode::kGnssOnly;
  // [output]
  std::string json_path = "-";   ///< JSON lines: "-" for stdout, or a file path

  /// Validates a parsed file. @throws ConfigError naming file, line and key.
  static NavdConfig FromFile(const ConfigFile& file);
};

}  // namespace hil::estimator

#pragma once
/// @file
/// Test support: gpsd's expected output (`<log>.chk`, JSON lines of its regression suite) for the
/// real u-blox 5 captures in the project's shared folder (../shared/vectors/gpsd-ublox5, never
/// copied into the checkout), read as one reference epoch per reported time.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hil::estimator::testing {

/// What gpsd reported for one time (the TPVs of that time merged: gpsd reports an epoch several
/// times as its sentences or messages arrive; the last value of each field is its final word).
struct GpsdEpoch {
  std::int64_t unix_ns = 0;  ///< "time", UTC
  int mode = 0;              ///< highest "mode" of the time: 1 no fix, 2 2-D, 3 3-D
  std::optional<double> lat_deg, lon_deg, alt_hae_m, speed_mps, track_deg;
};

struct GpsdReport {
  std::vector<GpsdEpoch> epochs;  ///< in time order
  int timeless_tpvs = 0;          ///< TPVs without a time (gpsd's "no fix, no time" reports)
};

/// The folder of the gpsd vectors (HIL_GPSD_VECTORS_DIR, set by CMake).
std::string GpsdVectorsDir();
/// The five logs, each with the protocol it carries ("nmea" or "ubx").
struct GpsdLog {
  std::string name, protocol;
};
const std::vector<GpsdLog>& GpsdLogs();
/// Reads `<dir>/<name>.chk`; throws std::runtime_error naming the file and line on bad input.
GpsdReport ReadGpsdChk(const std::string& chk_path);
/// "2024-03-28T15:14:05.000Z" as Unix nanoseconds (throws on another form).
std::int64_t UnixNsFromIso(const std::string& iso);
/// The whole file's bytes.
std::string ReadBytes(const std::string& path);

}  // namespace hil::estimator::testing

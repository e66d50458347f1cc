#pragma once
/// @file
/// Joins the sentences of one NMEA epoch (RMC for the date, speed and course; GGA for position,
/// altitude and quality) into a GNSS measurement with a full UTC time of validity.

#include <cstdint>
#include <optional>

#include "hil/estimator/drivers/nmea_decoder.h"

namespace hil::estimator::drivers {

/// A GNSS position/velocity measurement from NMEA, time-stamped by the receiver.
struct NmeaMeasurement {
  std::int64_t tov_unix_ns = 0;                   ///< epoch time, UTC
  double lat_deg = 0, lon_deg = 0, height_m = 0;  ///< height above the ellipsoid
  std::optional<double> speed_mps, course_deg;
  std::optional<double> hdop;
  std::optional<double> geoid_separation_m;  ///< GGA's geoid height (height_m includes it)
  double altitude_step_m = 0.0;              ///< GGA altitude's resolution (NmeaFix)
  int quality = 0, num_sv = 0;
};

/// Stateful joiner: remembers the last date and the RMC of the current epoch.
class NmeaEpochAssembler {
 public:
  /// Returns a measurement when `fix` completes one (a valid GGA with a known date).
  std::optional<NmeaMeasurement> Add(const NmeaFix& fix);

 private:
  std::optional<std::int64_t> day_start_unix_ns_;  // midnight of the last RMC date
  std::optional<std::int64_t> rmc_time_of_day_ns_;
  std::optional<double> rmc_speed_mps_, rmc_course_deg_;
};

}  // namespace hil::estimator::drivers

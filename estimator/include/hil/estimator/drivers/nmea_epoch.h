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
  /// VDOP of the last GSA with a 3-D solution, within kVdopMaxAge of GGA time before this epoch
  std::optional<double> vdop;
  std::optional<double> geoid_separation_m;  ///< GGA's geoid height (height_m includes it)
  double altitude_step_m = 0.0;              ///< GGA altitude's resolution (NmeaFix)
  double geoid_step_m = 0.0;                 ///< GGA geoid separation's resolution (NmeaFix)
  int quality = 0, num_sv = 0;
};

/// Stateful joiner: remembers the last date, the RMC of the current epoch and the last GSA's VDOP.
class NmeaEpochAssembler {
 public:
  /// A GSA's VDOP is kept for the GGAs of up to 5 s after the GGA before it (GSA carries no time;
  /// receivers send it once per epoch or once a second)
  static constexpr std::int64_t kVdopMaxAgeNs = 5'000'000'000LL;
  /// Returns a measurement when `fix` completes one (a valid GGA with a known date).
  std::optional<NmeaMeasurement> Add(const NmeaFix& fix);

 private:
  std::optional<std::int64_t> day_start_unix_ns_;  // midnight of the last RMC date
  std::optional<std::int64_t> rmc_time_of_day_ns_;
  std::optional<double> rmc_speed_mps_, rmc_course_deg_;
  std::optional<std::int64_t> gga_time_of_day_ns_;   // the last GGA's
  std::optional<double> vdop_;                       // the last GSA's (3-D solution)
  std::optional<std::int64_t> vdop_time_of_day_ns_;  // the GGA time before that GSA
};

}  // namespace hil::estimator::drivers

#include "hil/estimator/drivers/nmea_epoch.h"

#include <cstdlib>

namespace hil::estimator::drivers {
namespace {

constexpr std::int64_t kNsPerDay = 86400LL * 1000000000LL;

std::int64_t DaysFromCivil(int y, int m, int d) {
  y -= m <= 2;
  const int era = (y >= 0 ? y : y - 399) / 400;
  const int yoe = y - era * 400;
  const int doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return static_cast<std::int64_t>(era) * 146097 + doe - 719468;
}

}  // namespace

std::optional<NmeaMeasurement> NmeaEpochAssembler::Add(const NmeaFix& fix) {
  if (fix.kind == NmeaFix::Kind::kRmc) {
    if (fix.day && fix.month && fix.year) {
      day_start_unix_ns_ = DaysFromCivil(*fix.year, *fix.month, *fix.day) * kNsPerDay;
    }
    rmc_time_of_day_ns_ = fix.utc_time_of_day_ns;
    rmc_speed_mps_ = fix.valid ? fix.speed_mps : std::nullopt;
    rmc_course_deg_ = fix.valid ? fix.course_deg : std::nullopt;
    return std::nullopt;
  }
  if (fix.kind == NmeaFix::Kind::kGsa) {
    vdop_ = fix.vdop;
    vdop_time_of_day_ns_ = gga_time_of_day_ns_;
    return std::nullopt;
  }
  gga_time_of_day_ns_ = fix.utc_time_of_day_ns;
  if (!fix.valid || !fix.utc_time_of_day_ns || !day_start_unix_ns_ || !fix.msl_altitude_m)
    return std::nullopt;
  NmeaMeasurement m;
  std::int64_t day = *day_start_unix_ns_;
  // a GGA just after midnight following an RMC of the previous day
  if (rmc_time_of_day_ns_ && *fix.utc_time_of_day_ns + kNsPerDay / 2 < *rmc_time_of_day_ns_)
    day += kNsPerDay;
  m.tov_unix_ns = day + *fix.utc_time_of_day_ns;
  m.lat_deg = *fix.lat_deg;
  m.lon_deg = *fix.lon_deg;
  m.height_m = *fix.msl_altitude_m + fix.geoid_separation_m.value_or(0.0);
  m.hdop = fix.hdop;
  if (vdop_ && vdop_time_of_day_ns_ &&
      std::abs(*fix.utc_time_of_day_ns - *vdop_time_of_day_ns_) <= kVdopMaxAgeNs)
    m.vdop = vdop_;
  m.geoid_separation_m = fix.geoid_separation_m;
  m.altitude_step_m = fix.altitude_step_m;
  m.geoid_step_m = fix.geoid_step_m;  // 0 when the GGA has no geoid separation
  m.quality = fix.quality;
  m.num_sv = fix.num_sv;
  if (rmc_time_of_day_ns_ == fix.utc_time_of_day_ns) {
    m.speed_mps = rmc_speed_mps_;
    m.course_deg = rmc_course_deg_;
  }
  return m;
}

}  // namespace hil::estimator::drivers

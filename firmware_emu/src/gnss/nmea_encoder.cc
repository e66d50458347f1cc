#include "hil/firmware_emu/gnss/nmea_encoder.h"

#include <cstdio>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/nmea_sentence.h"

namespace hil::gnss::nmea {
namespace {

constexpr double kKnotsPerMps = 3600.0 / 1852.0;

// hhmmss.ss of the epoch, rounded to centiseconds.
std::string FormatTime(std::int64_t unix_ns) {
  const std::int64_t cs = (unix_ns + 5000000) / 10000000;  // centiseconds
  const UtcTime u = UtcFromUnixNs(cs * 10000000);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%02d%02d%02d.%02lld", u.hour, u.minute, u.second,
                static_cast<long long>(u.nanosecond / 10000000));
  return buf;
}

std::string FormatDate(std::int64_t unix_ns) {
  const UtcTime u = UtcFromUnixNs(unix_ns);
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02d%02d%02d", u.day, u.month, u.year % 100);
  return buf;
}

char ModeIndicator(const GnssFix& fix) {
  if (!fix.valid()) return 'N';
  return fix.quality == FixQuality::kDgps ? 'D' : 'A';
}

}  // namespace

std::string EncodeRmc(const GnssFix& fix, bool time_known) {
  std::string b = "GPRMC,";
  b += time_known ? FormatTime(fix.unix_ns) : "";
  if (fix.valid()) {
    b += ",A,";
    b += FormatLatitude(fix.lat_deg) + "," + FormatLongitude(fix.lon_deg) + ",";
    const double speed = fix.ground_speed_mps();
    b += FormatFixed(speed * kKnotsPerMps, 3) + ",";
    if (speed >= kCourseMinSpeed_mps) b += FormatFixed(fix.course_deg(), 2);
    b += ",";
  } else {
    b += ",V,,,,,,,";
  }
  b += time_known ? FormatDate(fix.unix_ns) : "";
  b += ",,,";
  b += ModeIndicator(fix);
  return Frame(b);
}

std::string EncodeGga(const GnssFix& fix, bool time_known) {
  std::string b = "GPGGA,";
  b += time_known ? FormatTime(fix.unix_ns) : "";
  if (!fix.valid()) {
    b += ",,,,,0,00,99.99,,,,,,";
    return Frame(b);
  }
  char sats[8];
  std::snprintf(sats, sizeof sats, "%02d", fix.num_sv);
  b += "," + FormatLatitude(fix.lat_deg) + "," + FormatLongitude(fix.lon_deg) + ",";
  b += std::to_string(static_cast<int>(fix.quality)) + "," + sats + ",";
  b += FormatFixed(fix.hdop, 2) + ",";
  b += FormatFixed(fix.height_m - fix.geoid_separation_m, 1) + ",M,";
  b += FormatFixed(fix.geoid_separation_m, 1) + ",M,,";
  return Frame(b);
}

}  // namespace hil::gnss::nmea

#include "hil/firmware_emu/gnss/nmea_encoder.h"

#include <cstdio>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/nmea_sentence.h"

namespace hil::gnss::nmea {
namespace {

constexpr double kKnotsPerMps = 3600.0 / 1852.0;
constexpr double kKmhPerMps = 3.6;

char ModeIndicator(const GnssFix& fix) {
  if (!fix.valid()) return 'N';
  return fix.quality == FixQuality::kGps ? 'A' : 'D';
}

std::string Position(const GnssFix& fix, const NmeaFormat& f) {
  return FormatLatitude(fix.lat_deg, f.minute_decimals) + "," +
         FormatLongitude(fix.lon_deg, f.minute_decimals);
}

}  // namespace

std::string FormatTime(UnixTime utc) {
  const std::int64_t cs = (ToNs(utc) + 5000000) / 10000000;  // centiseconds
  const UtcTime u = UtcFrom(UnixTimeFromNs(cs * 10000000));
  char buf[48];
  std::snprintf(buf, sizeof buf, "%02d%02d%02d.%02lld", u.hour, u.minute, u.second,
                static_cast<long long>(u.nanosecond / 10000000));
  return buf;
}

std::string FormatDate(UnixTime utc) {
  const UtcTime u = UtcFrom(utc);
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d%02d%02d", u.day, u.month, u.year % 100);
  return buf;
}

std::string EncodeRmc(const GnssFix& fix, bool time_known, const NmeaFormat& f) {
  std::string b = "GPRMC,";
  b += time_known ? FormatTime(fix.utc) : "";
  if (fix.valid()) {
    b += ",A,";
    b += Position(fix, f) + ",";
    const double speed = fix.ground_speed_mps();
    b += FormatFixed(speed * kKnotsPerMps, 3) + ",";
    if (speed >= kCourseMinSpeed_mps) b += FormatFixed(fix.course_deg(), 2);
    b += ",";
  } else {
    b += ",V,,,,,,,";
  }
  b += time_known ? FormatDate(fix.utc) : "";
  b += ",,";
  if (f.mode_indicator) {
    b += ",";
    b += ModeIndicator(fix);
  }
  return Frame(b);
}

std::string EncodeGga(const GnssFix& fix, bool time_known, const NmeaFormat& f) {
  std::string b = "GPGGA,";
  b += time_known ? FormatTime(fix.utc) : "";
  if (!fix.valid()) {
    b += ",,,,,0,00,99.99,,,,,,";
    return Frame(b);
  }
  char sats[8];
  std::snprintf(sats, sizeof sats, "%02d", fix.num_sv);
  b += "," + Position(fix, f) + ",";
  b += std::to_string(static_cast<int>(fix.quality)) + "," + sats + ",";
  b += FormatFixed(fix.hdop, 2) + ",";
  b += FormatFixed(fix.height_m - fix.geoid_separation_m, 1) + ",M,";
  b += FormatFixed(fix.geoid_separation_m, 1) + ",M,";
  if (f.diff_station && fix.quality != FixQuality::kGps)
    b += "1.0,0000";
  else
    b += ",";
  return Frame(b);
}

std::string EncodeVtg(const GnssFix& fix, const NmeaFormat& f) {
  std::string b = "GPVTG,";
  if (!fix.valid()) {
    b += ",,,,,,,";
    if (f.mode_indicator) b += ",N";
    return Frame(b);
  }
  const double speed = fix.ground_speed_mps();
  if (speed >= kCourseMinSpeed_mps) b += FormatFixed(fix.course_deg(), 2);
  b += ",T,,M,";
  b += FormatFixed(speed * kKnotsPerMps, 3) + ",N,";
  b += FormatFixed(speed * kKmhPerMps, 3) + ",K";
  if (f.mode_indicator) {
    b += ",";
    b += ModeIndicator(fix);
  }
  return Frame(b);
}

std::string EncodeGll(const GnssFix& fix, bool time_known, const NmeaFormat& f) {
  std::string b = "GPGLL,";
  b += fix.valid() ? Position(fix, f) : ",,,";
  b += ",";
  b += time_known ? FormatTime(fix.utc) : "";
  b += fix.valid() ? ",A" : ",V";
  if (f.mode_indicator) {
    b += ",";
    b += ModeIndicator(fix);
  }
  return Frame(b);
}

std::string EncodeZda(const GnssFix& fix, bool time_known) {
  std::string b = "GPZDA,";
  if (time_known) {
    const UtcTime u = UtcFrom(fix.utc);
    char buf[48];
    std::snprintf(buf, sizeof buf, ",%02d,%02d,%04d,00,00", u.day, u.month, u.year);
    b += FormatTime(fix.utc) + buf;
  } else {
    b += ",,,,00,00";
  }
  return Frame(b);
}

}  // namespace hil::gnss::nmea

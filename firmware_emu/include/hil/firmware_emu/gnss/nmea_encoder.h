#pragma once
/// @file
/// NMEA 0183 sentence encoders for a u-blox 5 (firmware 6.x formats, NMEA 2.3, talker GP): the
/// fix sentences RMC, GGA, VTG, GLL and ZDA. Each takes a protocol-neutral GnssFix and returns one
/// framed sentence ("$...*HH\r\n"). Field layouts and no-fix rules: shared/reference/ublox5.md §3.

#include <string>

#include "hil/firmware_emu/gnss/gnss_fix.h"

namespace hil::gnss::nmea {

/// Speeds in an RMC/VTG below this are printed without a course (firmware-6 behaviour: the course
/// field is empty when stationary).
inline constexpr double kCourseMinSpeed_mps = 0.5 / 3.6;

/// Number formats of a profile. The defaults are the u-blox 5 firmware-6 formats.
struct NmeaFormat {
  int minute_decimals = 5;     ///< lat/lon minutes
  bool mode_indicator = true;  ///< NMEA 2.3 mode field in RMC, VTG, GLL (CFG-NMEA version 0x23)
  bool diff_station = false;   ///< GGA age/station filled when the fix is differential (RTK)
};

/// `$GPRMC` — recommended minimum data. The date is kept without a fix once time is known.
std::string EncodeRmc(const GnssFix& fix, bool time_known = true, const NmeaFormat& f = {});
/// `$GPGGA` — fix data. Without a fix: time, quality 0, `00` satellites, HDOP 99.99, rest empty.
std::string EncodeGga(const GnssFix& fix, bool time_known = true, const NmeaFormat& f = {});
/// `$GPVTG` — course and speed. Without a fix every field is empty, even the unit letters.
std::string EncodeVtg(const GnssFix& fix, const NmeaFormat& f = {});
/// `$GPGLL` — position and time.
std::string EncodeGll(const GnssFix& fix, bool time_known = true, const NmeaFormat& f = {});
/// `$GPZDA` — UTC date and time (local zone 00,00).
std::string EncodeZda(const GnssFix& fix, bool time_known = true);

/// `hhmmss.ss` of a UTC instant, rounded to centiseconds.
std::string FormatTime(UnixTime utc);
/// `ddmmyy` of a UTC instant.
std::string FormatDate(UnixTime utc);

}  // namespace hil::gnss::nmea

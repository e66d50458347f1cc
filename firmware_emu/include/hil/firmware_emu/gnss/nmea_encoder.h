#pragma once
/// @file
/// NMEA 0183 sentence encoders for a u-blox 5 (firmware 6.x formats, NMEA 2.3, talker GP).
/// Each takes a protocol-neutral GnssFix and returns one framed sentence ("$...*HH\r\n").
/// Field layouts and no-fix rules: shared/reference/ublox5.md §3.

#include <string>

#include "hil/firmware_emu/gnss/gnss_fix.h"

namespace hil::gnss::nmea {

/// Speeds in an RMC/VTG below this are printed without a course (firmware-6 behaviour: the course
/// field is empty when stationary).
inline constexpr double kCourseMinSpeed_mps = 0.5 / 3.6;

/// `$GPRMC` — recommended minimum data. The date is kept without a fix once time is known.
std::string EncodeRmc(const GnssFix& fix, bool time_known = true);
/// `$GPGGA` — fix data. Without a fix: time, quality 0, `00` satellites, HDOP 99.99, rest empty.
std::string EncodeGga(const GnssFix& fix, bool time_known = true);

}  // namespace hil::gnss::nmea

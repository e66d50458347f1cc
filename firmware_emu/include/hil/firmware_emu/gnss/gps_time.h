#pragma once
/// @file
/// GPS and UTC calendar arithmetic for the receiver emulators: GPS week / time of week, UTC with
/// leap seconds, calendar dates. Pure integer arithmetic; no time zone, no wall clock.

#include <cstdint>
#include <string>

#include "hil/firmware_emu/unix_time.h"

namespace hil::gnss {

/// Seconds between the Unix epoch (1970-01-01) and the GPS epoch (1980-01-06), both UTC.
inline constexpr std::int64_t kGpsEpochUnix_s = 315964800;
inline constexpr std::int64_t kSecondsPerWeek = 604800;

/// A UTC calendar instant with nanoseconds.
struct UtcTime {
  int year = 1970, month = 1, day = 1;  ///< calendar date
  int hour = 0, minute = 0, second = 0;
  std::int64_t nanosecond = 0;
};

/// GPS time as the receivers write it: the week number (full, not modulo 1024) and the time of
/// week. A calendar form, like UtcTime; the instant type of GPS time is the estimator's `GpsTime`.
struct GpsWeekTime {
  int week = 0;
  std::int64_t tow_ns = 0;  ///< nanoseconds into the week
  double tow_s() const { return static_cast<double>(tow_ns) * 1e-9; }
  std::uint32_t itow_ms() const { return static_cast<std::uint32_t>(tow_ns / 1000000); }
};

/// Days since 1970-01-01 of a proleptic Gregorian date.
std::int64_t DaysFromCivil(int year, int month, int day);
/// The UTC instant (no leap seconds counted, as Unix time) of a calendar instant.
UnixTime UnixTimeFromUtc(const UtcTime& utc);
/// Calendar instant of a UTC instant.
UtcTime UtcFrom(UnixTime t);
/// GPS − UTC in whole seconds at a UTC instant (IERS table from 1980 to the 2017 leap second).
int LeapSecondsAt(UnixTime t);
/// GPS time of a UTC instant.
GpsWeekTime GpsFrom(UnixTime t);
/// The UTC instant of a GPS time.
UnixTime UnixTimeFromGps(const GpsWeekTime& gps);
/// Parses "YYYY-MM-DDThh:mm:ss[.fff]Z".
/// @throws std::invalid_argument naming the text when it does not parse or is out of range.
UnixTime ParseIsoUtc(const std::string& text);

}  // namespace hil::gnss

#pragma once
/// @file
/// Time in the estimator: one instant type, `GpsTime`, integer nanoseconds of GPS time since the
/// GPS epoch (1980-01-06) on the `GpsClock`, mapped from each device's own clock (GPS time from the
/// receiver, the MCU tick through the latched time pulse). Durations are integer nanoseconds
/// (`Nanoseconds`). Host arrival times are never used by the filter.

#include <chrono>
#include <cstdint>

namespace hil::estimator {

/// Clock tag for GPS time (no leap seconds); never read: instants come from the devices.
struct GpsClock {
  using rep = std::int64_t;
  using period = std::nano;
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<GpsClock, duration>;
  static constexpr bool is_steady = true;
};

using Nanoseconds = std::chrono::nanoseconds;
/// An instant of GPS time.
using GpsTime = GpsClock::time_point;

inline constexpr std::int64_t kNsPerSecond = 1000000000;
/// Unix seconds of the GPS epoch (1980-01-06T00:00:00Z).
inline constexpr std::int64_t kGpsEpochUnix_s = 315964800;
inline constexpr std::int64_t kSecondsPerGpsWeek = 604800;

/// GPS time from integer nanoseconds since the GPS epoch.
constexpr GpsTime GpsTimeFromNs(std::int64_t ns) { return GpsTime{Nanoseconds{ns}}; }
/// Nanoseconds since the GPS epoch.
constexpr std::int64_t ToNs(GpsTime t) { return t.time_since_epoch().count(); }
/// GPS time of a week number (not wrapped) and the nanoseconds into that week.
constexpr GpsTime GpsTimeFromWeek(std::int64_t week, std::int64_t ns_of_week) {
  return GpsTimeFromNs(week * kSecondsPerGpsWeek * kNsPerSecond + ns_of_week);
}

/// UTC Unix nanoseconds from GPS time, given GPS − UTC in seconds.
constexpr std::int64_t UnixNsFromGpsTime(GpsTime t, int leap_s) {
  return ToNs(t) + (kGpsEpochUnix_s - leap_s) * kNsPerSecond;
}
/// GPS time from UTC Unix nanoseconds, given GPS − UTC in seconds.
constexpr GpsTime GpsTimeFromUnixNs(std::int64_t unix_ns, int leap_s) {
  return GpsTimeFromNs(unix_ns - (kGpsEpochUnix_s - leap_s) * kNsPerSecond);
}

}  // namespace hil::estimator

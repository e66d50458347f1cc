#pragma once
/// @file
/// Time in the estimator: integer nanoseconds on one time base, GPS time since the GPS epoch
/// (1980-01-06), mapped from each device's own clock (GPS time from the receiver, the MCU tick
/// through the latched time pulse). Host arrival times are never used by the filter.

#include <cstdint>

namespace hil::estimator {

/// Nanoseconds of GPS time since the GPS epoch.
using GpsNs = std::int64_t;

inline constexpr std::int64_t kNsPerSecond = 1000000000;
/// Unix seconds of the GPS epoch (1980-01-06T00:00:00Z).
inline constexpr std::int64_t kGpsEpochUnix_s = 315964800;

/// UTC Unix nanoseconds from GPS time, given GPS − UTC in seconds.
constexpr std::int64_t UnixNsFromGpsNs(GpsNs t, int leap_s) {
  return t + (kGpsEpochUnix_s - leap_s) * kNsPerSecond;
}
/// GPS time from UTC Unix nanoseconds, given GPS − UTC in seconds.
constexpr GpsNs GpsNsFromUnixNs(std::int64_t unix_ns, int leap_s) {
  return unix_ns - (kGpsEpochUnix_s - leap_s) * kNsPerSecond;
}

}  // namespace hil::estimator

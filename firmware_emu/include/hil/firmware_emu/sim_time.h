#pragma once
/// @file
/// The one time type of the harness and its emulators: integer nanoseconds since the start of a
/// scenario (t = 0 at the scenario's `start_utc`). Double seconds appear only at the CVODE boundary
/// and in human-facing output; conversions go through the helpers below.

#include <chrono>
#include <cstdint>

namespace hil {

/// Clock tag for emulated (scenario) time; it is never tied to the wall clock.
struct SimClock {
  using rep = std::int64_t;
  using period = std::nano;
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<SimClock, duration>;
  static constexpr bool is_steady = true;
};

using Duration = std::chrono::nanoseconds;
using Time = SimClock::time_point;

/// Nanoseconds in a (UTC, leap-second-free) day, for time-of-day fields on the wire.
inline constexpr std::int64_t kDayNs = 86400LL * 1000000000LL;

/// Time from integer nanoseconds since scenario start.
constexpr Time TimeFromNs(std::int64_t ns) { return Time{Duration{ns}}; }
/// Nanoseconds since scenario start.
constexpr std::int64_t ToNs(Time t) { return t.time_since_epoch().count(); }
/// Seconds since scenario start, for CVODE and human-facing output only.
constexpr double ToSeconds(Time t) { return static_cast<double>(ToNs(t)) * 1e-9; }
constexpr double ToSeconds(Duration d) { return static_cast<double>(d.count()) * 1e-9; }
/// Rounds seconds to the nearest nanosecond.
constexpr Time TimeFromSeconds(double s) {
  return TimeFromNs(static_cast<std::int64_t>(s * 1e9 + (s >= 0 ? 0.5 : -0.5)));
}
constexpr Duration DurationFromSeconds(double s) {
  return Duration{static_cast<std::int64_t>(s * 1e9 + (s >= 0 ? 0.5 : -0.5))};
}
/// Period of a rate in hertz, rounded to the nanosecond.
constexpr Duration PeriodFromHz(double hz) { return DurationFromSeconds(1.0 / hz); }

}  // namespace hil

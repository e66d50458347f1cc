#pragma once
/// @file
/// UTC as the kernel's CLOCK_REALTIME and the log formats count it: integer nanoseconds since the
/// Unix epoch (1970-01-01T00:00:00Z), leap seconds not counted. A scenario's start_utc, kernel
/// receive stamps and candump timestamps are `UnixTime`; emulated `Time` and `WallTime`
/// (CLOCK_MONOTONIC) are other clocks, and mixing them does not compile. Emulated t maps onto UTC
/// as `start + (t - Time{})`. (gnss::UtcTime is the calendar form of the same instants.)

#include <time.h>

#include <chrono>
#include <cstdint>

#include "hil/firmware_emu/sim_time.h"

namespace hil {

/// Clock tag for UTC (CLOCK_REALTIME).
struct UnixClock {
  using rep = std::int64_t;
  using period = std::nano;
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<UnixClock, duration>;
  static constexpr bool is_steady = false;
  /// CLOCK_REALTIME now.
  static time_point now() noexcept {
    timespec ts{};
    clock_gettime(CLOCK_REALTIME, &ts);
    return time_point{duration{static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec}};
  }
};

/// An instant of UTC.
using UnixTime = UnixClock::time_point;

/// UnixTime from nanoseconds since the Unix epoch (a file's or the kernel's count).
constexpr UnixTime UnixTimeFromNs(std::int64_t ns) { return UnixTime{Duration{ns}}; }
/// Nanoseconds since the Unix epoch, for files and the kernel.
constexpr std::int64_t ToNs(UnixTime t) { return t.time_since_epoch().count(); }
/// The UTC instant of emulated `t` in a run that starts (t = 0) at UTC `start`.
constexpr UnixTime UtcAt(UnixTime start, Time t) { return start + (t - Time{}); }

/// The first epoch after `after` on the grid of `period` counted from the Unix epoch, as emulated
/// time of a run that starts at UTC `start`: receivers put their epochs on the UTC (and GPS:
/// GPS − UTC is whole seconds) grid of their measurement period, whole seconds at 1 Hz.
constexpr Time NextGridEpoch(Time after, Duration period, UnixTime start) {
  const std::int64_t period_ns = period.count();
  const std::int64_t abs_after = ToNs(UtcAt(start, after));
  std::int64_t k = abs_after / period_ns + 1;
  if (abs_after < 0 && abs_after % period_ns != 0) k -= 1;
  return TimeFromNs(k * period_ns - ToNs(start));
}

}  // namespace hil

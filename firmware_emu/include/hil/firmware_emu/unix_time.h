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

}  // namespace hil

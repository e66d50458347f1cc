#pragma once
/// @file
/// The wall clock of the machine running the harness: CLOCK_MONOTONIC, integer nanoseconds since
/// an unspecified instant (boot). Real-time and scaled runs map emulated `Time` onto it
/// (link::RealtimePacer); captures record it. `WallTime` and `Time` are instants of different
/// clocks: subtracting or comparing one with the other does not compile. Their differences are
/// both `Duration` (std::chrono::nanoseconds), as in <chrono>; a pacer scales one into the other.

#include <time.h>

#include <chrono>
#include <cstdint>

#include "hil/firmware_emu/sim_time.h"

namespace hil {

/// Clock tag for CLOCK_MONOTONIC.
struct WallClock {
  using rep = std::int64_t;
  using period = std::nano;
  using duration = std::chrono::nanoseconds;
  using time_point = std::chrono::time_point<WallClock, duration>;
  static constexpr bool is_steady = true;
  /// CLOCK_MONOTONIC now.
  static time_point now() noexcept {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return time_point{duration{static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec}};
  }
};

/// An instant of CLOCK_MONOTONIC.
using WallTime = WallClock::time_point;

/// CLOCK_MONOTONIC now.
inline WallTime WallNow() { return WallClock::now(); }
/// WallTime from CLOCK_MONOTONIC nanoseconds (a capture's t_wall_ns, a kernel stamp).
constexpr WallTime WallTimeFromNs(std::int64_t ns) { return WallTime{Duration{ns}}; }
/// CLOCK_MONOTONIC nanoseconds, for files and the kernel's timespec.
constexpr std::int64_t ToNs(WallTime t) { return t.time_since_epoch().count(); }
/// The same instant on std::chrono::steady_clock (CLOCK_MONOTONIC in libstdc++), for
/// sleep_until and condition_variable::wait_until.
inline std::chrono::steady_clock::time_point ToSteady(WallTime t) {
  return std::chrono::steady_clock::time_point(
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(t.time_since_epoch()));
}

}  // namespace hil

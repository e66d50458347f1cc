#pragma once
/// @file
/// Maps emulated time onto the wall clock for real-time and scaled runs, and sleeps until an
/// emulated instant: clock_nanosleep to within ~60 µs, then a short busy-wait, which on these
/// machines gives p50 ≈ 3 µs and p99 ≈ 11 µs of schedule error (shared/DESIGN.md, Time).

#include <cstdint>

#include "hil/firmware_emu/sim_time.h"

namespace hil::link {

/// Wall-clock pacing of emulated time. speed = 1 is real time, 10 is ten times faster.
class RealtimePacer {
 public:
  /// Starts the mapping now: emulated t = 0 is the current CLOCK_MONOTONIC instant.
  explicit RealtimePacer(double speed = 1.0);
  /// Sleeps until the wall instant of emulated time `t`. Returns the wall time reached (ns,
  /// CLOCK_MONOTONIC) so callers can record the schedule error.
  std::int64_t SleepUntil(Time t) const;
  /// CLOCK_MONOTONIC instant of emulated time `t`.
  std::int64_t WallNsOf(Time t) const;
  /// Emulated time that corresponds to a CLOCK_MONOTONIC instant.
  Time SimTimeOfWall(std::int64_t wall_ns) const;

  /// Lowers the timer slack and asks for SCHED_FIFO when the process may have it.
  /// Returns true when real-time scheduling was granted.
  static bool RequestRealtimeScheduling();
  /// CLOCK_MONOTONIC now, in nanoseconds.
  static std::int64_t MonotonicNs();

 private:
  double speed_;
  std::int64_t wall_start_ns_;
};

}  // namespace hil::link

#pragma once
/// @file
/// Maps emulated time onto the wall clock for real-time and scaled runs, and sleeps until an
/// emulated instant: clock_nanosleep to within ~60 µs, then a short busy-wait, which on these
/// machines gives p50 ≈ 3 µs and p99 ≈ 11 µs of schedule error (shared/DESIGN.md, Time).

#include <cstdint>
#include <string>

#include "hil/firmware_emu/sim_time.h"

namespace hil::link {

/// The scheduling a thread really has, read back from the kernel (not what it asked for).
struct ThreadSchedule {
  std::string policy;       ///< "SCHED_FIFO", "SCHED_RR", "SCHED_OTHER", …
  int priority = 0;         ///< real-time priority (0 for SCHED_OTHER)
  long timer_slack_ns = 0;  ///< PR_GET_TIMERSLACK
  int tid = 0;              ///< the thread's id (gettid)
  std::string refused;      ///< why SCHED_FIFO was not granted (empty when it was)
  bool realtime() const { return policy == "SCHED_FIFO" || policy == "SCHED_RR"; }
};

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

  /// Lowers the calling thread's timer slack to 1 ns and asks SCHED_FIFO at `priority` for it
  /// (for this thread only: threads it creates later inherit it, threads that exist keep theirs).
  /// Returns what the thread then has (ThreadSchedule::refused says why FIFO was not granted).
  static ThreadSchedule RequestRealtimeScheduling(int priority = 50);
  /// The calling thread's scheduling as the kernel reports it.
  static ThreadSchedule CurrentThreadSchedule();
  /// CLOCK_MONOTONIC now, in nanoseconds.
  static std::int64_t MonotonicNs();
  /// Whether the threads pacing by this clock ask for SCHED_FIFO (RequestRealtimeScheduling) or
  /// keep the scheduling they inherit (the run asked for no priority: `--nice` 0 or more).
  bool realtime_threads() const { return realtime_threads_; }
  void set_realtime_threads(bool on) { realtime_threads_ = on; }

 private:
  double speed_;
  bool realtime_threads_ = true;
  std::int64_t wall_start_ns_;
};

}  // namespace hil::link

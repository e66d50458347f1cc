#pragma once
/// @file
/// Maps emulated time onto the wall clock for real-time and scaled runs, and sleeps until an
/// emulated instant: clock_nanosleep (absolute, CLOCK_MONOTONIC) to the instant itself; only a
/// wait under 5 µs is spun. The schedule error is then the kernel's wake-up latency (cyclictest's
/// figure on the same machine), and the thread uses almost no CPU between its bytes.

#include <cstdint>
#include <optional>
#include <string>

#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/wall_time.h"

namespace hil::link {

/// The CPU a thread used over a stretch of wall time (getrusage RUSAGE_THREAD).
struct ThreadUsage {
  double user_s = 0, system_s = 0;  ///< CPU time in user space and in the kernel
  double wall_s = 0;                ///< wall time of the stretch
  double cpu_pct() const { return wall_s > 0 ? 100.0 * (user_s + system_s) / wall_s : 0.0; }
};

/// The calling thread's CPU times so far and the CLOCK_MONOTONIC instant they were read at; the
/// difference of two readings is a ThreadUsage.
struct ThreadCpuReading {
  double user_s = 0, system_s = 0;
  WallTime wall{};
  static ThreadCpuReading Now();
  ThreadUsage Since(const ThreadCpuReading& start) const;
};

/// The scheduling a thread really has, read back from the kernel (not what it asked for).
struct ThreadSchedule {
  std::string policy;                ///< "SCHED_FIFO", "SCHED_RR", "SCHED_OTHER", …
  int priority = 0;                  ///< real-time priority (0 for SCHED_OTHER)
  long timer_slack_ns = 0;           ///< PR_GET_TIMERSLACK
  int tid = 0;                       ///< the thread's id (gettid)
  std::string refused;               ///< why SCHED_FIFO was not granted (empty when it was)
  std::optional<ThreadUsage> usage;  ///< the CPU it used while the run paced (set at its end)
  bool realtime() const { return policy == "SCHED_FIFO" || policy == "SCHED_RR"; }
};

/// Wall-clock pacing of emulated time. speed = 1 is real time, 10 is ten times faster.
class RealtimePacer {
 public:
  /// Starts the mapping now: emulated t = 0 is the current CLOCK_MONOTONIC instant.
  explicit RealtimePacer(double speed = 1.0);
  /// Sleeps until the wall instant of emulated time `t`. Returns the wall time reached so callers
  /// can record the schedule error.
  WallTime SleepUntil(Time t) const;
  /// CLOCK_MONOTONIC instant of emulated time `t`.
  WallTime WallTimeOf(Time t) const;
  /// Emulated time that corresponds to a CLOCK_MONOTONIC instant.
  Time SimTimeOfWall(WallTime wall) const;

  /// Lowers the calling thread's timer slack to 1 ns and asks SCHED_FIFO at `priority` for it
  /// (for this thread only: threads it creates later inherit it, threads that exist keep theirs).
  /// Returns what the thread then has (ThreadSchedule::refused says why FIFO was not granted).
  static ThreadSchedule RequestRealtimeScheduling(int priority = 50);
  /// The calling thread's scheduling as the kernel reports it.
  static ThreadSchedule CurrentThreadSchedule();
  /// Whether the threads pacing by this clock ask for SCHED_FIFO (RequestRealtimeScheduling) or
  /// keep the scheduling they inherit (the run asked for no priority: `--nice` 0 or more).
  bool realtime_threads() const { return realtime_threads_; }
  void set_realtime_threads(bool on) { realtime_threads_ = on; }
  /// SleepUntil sleeps to this long before the instant and spins the rest.
  static constexpr Duration kSpin{30000};

 private:
  double speed_;
  bool realtime_threads_ = true;
  WallTime wall_start_{};
};

}  // namespace hil::link

#pragma once
/// @file
/// The CPU weight of a run's processes on a shared machine.
///
/// A run is a chain of hand-overs: hil writes a link, the host (navd, a controller) wakes, reads
/// and answers, hil goes on. Each hand-over wakes a process, and on a machine whose CPUs are
/// busy the woken one waits until the scheduler gives it a slice: beside two busy loops seed004's
/// hil main thread was preempted about 4 500 times and waited 0.74 ms each time (throughput.md,
/// session 16). A lower nice value weights the run's threads above the machine's other work of
/// the same scheduling group, so a wake-up gets the CPU at once; it does not make the run use
/// more CPU (it waits for its hosts most of the time). The nice value is per thread on Linux: it
/// is set on every thread of hil, and the threads and processes started afterwards (the
/// estimator, the controller, the run's worker threads) inherit it.

#include <string>

namespace hil::harness {

/// Nice value of a run's processes unless told otherwise (`hil run --nice`): the weight of a
/// nice −10 thread is 9.3 times a nice-0 one's.
inline constexpr int kDefaultRunNice = -10;

/// What the kernel gave (report.json `priority`).
struct RunPriority {
  int requested = 0;    ///< the nice value asked for (0: left as it was)
  int nice = 0;         ///< the main thread's nice value afterwards
  std::string refused;  ///< why it was not granted (no CAP_SYS_NICE, RLIMIT_NICE), else empty
};

/// Sets nice value `nice` (−20…19) on every thread of this process; 0 leaves the priority as it
/// is. A refusal is reported, not thrown: the run goes on at the priority it has.
RunPriority SetProcessNice(int nice);

}  // namespace hil::harness

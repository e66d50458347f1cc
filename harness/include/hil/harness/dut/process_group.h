#pragma once
/// @file
/// What the processes of a process group are doing, read from /proc: which of them are alive (a
/// zombie is not: it holds no file and runs no code, it only waits for its parent to reap it), and
/// whether all of them are asleep. Used to stop the estimator under test without waiting for
/// zombies to be reaped by an init that reaps late, and to see that it has finished its work.

#include <cstdint>
#include <vector>

namespace hil::harness {

/// Pids of the processes of process group `pgid` that are not zombies.
std::vector<int> LiveGroupMembers(int pgid);

/// A snapshot of the threads of a process group.
struct GroupActivity {
  bool readable = false;    ///< /proc could be read and the group has at least one live process
  bool all_asleep = false;  ///< every thread waits in an interruptible sleep (state S)
  /// Sum over the threads of their voluntary and involuntary context switches: a thread that
  /// woke up in between has switched at least once more.
  std::uint64_t switches = 0;
  int threads = 0;
};

/// Reads the state of every thread of every live process of group `pgid`.
GroupActivity ReadGroupActivity(int pgid);

/// True when two snapshots, taken in this order, show a group that slept all along: every thread
/// asleep in both, the same threads, and no context switch in between (no thread woke up).
bool SleptThroughout(const GroupActivity& before, const GroupActivity& after);

}  // namespace hil::harness

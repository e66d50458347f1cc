#pragma once
/// @file
/// What the processes of a process group are doing, read from /proc: which of them are alive (a
/// zombie is not: it holds no file and runs no code, it only waits for its parent to reap it), and
/// whether all of them are asleep. Used to stop the estimator under test without waiting for
/// zombies to be reaped by an init that reaps late, and to see that it has finished its work.

#include <cstdint>
#include <string>
#include <vector>

namespace hil::harness {

/// Pids of the processes of process group `pgid` that are not zombies.
std::vector<int> LiveGroupMembers(int pgid);

/// The state letter of thread `tid` of process `pid` (/proc/PID/task/TID/stat: R, S, D, Z, …;
/// ' ' when it cannot be read).
char ThreadState(int pid, int tid);

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

/// Whether every thread of a process group sleeps, cheaply enough to ask thousands of times a
/// second: the threads' /proc stat and children files stay open and are read again in place. The
/// list of threads is read afresh (a scan of /proc, which costs milliseconds on a busy machine)
/// only on the first call and when a thread has ended, a process's thread count changed or a
/// thread's children changed (a fork: a group grows only by its members' children).
class GroupSleepProbe {
 public:
  explicit GroupSleepProbe(int pgid) : pgid_(pgid) {}
  ~GroupSleepProbe();
  GroupSleepProbe(const GroupSleepProbe&) = delete;
  GroupSleepProbe& operator=(const GroupSleepProbe&) = delete;

  /// True when the group has a live thread and every live thread is in an interruptible sleep
  /// (state S): waiting for input, a timer or a child.
  bool AllAsleep();

 private:
  struct Task {
    int fd = -1;
    int children_fd = -1;  ///< /proc/…/task/…/children (-1: not available)
    std::string children;  ///< its text when the list was read
    bool process = false;  ///< the task is its process's main thread (its stat has num_threads)
    long threads = 0;      ///< the process's thread count when the list was read
  };
  void ReadTasks();
  void CloseTasks();

  int pgid_;
  std::vector<Task> tasks_;
};

}  // namespace hil::harness

#pragma once
/// @file
/// Nothing a run starts outlives it, even when hil itself is killed with SIGKILL (issue 40.1: an
/// orphan navd kept hil's captures open, grabbed the next run's ptys and read bytes typed into an
/// unrelated terminal that later got its pty). Two layers:
///   - every host process hil spawns gets PR_SET_PDEATHSIG SIGKILL (shell_spawn.h): it dies with
///     hil's main thread, which spawns it and lives as long as the run;
///   - what those processes start in turn (a shell's children, a helper) does not inherit that
///     signal, so a reaper process, forked when the run starts, holds the read end of a pipe whose
///     only write end is hil's. hil tells it the process groups the run owns; when the pipe ends
///     without hil saying it is done with a group (hil died, however), the reaper kills every
///     group it was given with SIGKILL, waits until none of their processes is alive, and exits.
/// The reaper runs in a session of its own (a signal to hil's process group or terminal does not
/// reach it) and may keep one descriptor of hil's open while it works: the run folder's lock
/// (folder_lock.h), so that no next run can start in the folder before the last orphan is gone.

#include <sys/types.h>

namespace hil::harness {

class GroupReaper {
 public:
  /// Forks the reaper. Call before the run starts threads (the child continues as a copy of a
  /// one-threaded process). `keep_fd` (or -1) stays open in the reaper until it exits.
  /// @throws std::runtime_error when the pipe or the fork fails.
  explicit GroupReaper(int keep_fd = -1);
  /// Tells the reaper to exit without killing anything and waits for it.
  ~GroupReaper();
  GroupReaper(const GroupReaper&) = delete;
  GroupReaper& operator=(const GroupReaper&) = delete;

  /// Process group `pgid` belongs to the run: killed if hil dies before Release(pgid).
  void Watch(pid_t pgid);
  /// The run has stopped group `pgid` itself: the reaper forgets it (its id may be reused).
  void Release(pid_t pgid);
  pid_t pid() const { return pid_; }

 private:
  void Send(int value);
  pid_t pid_ = -1;
  int write_fd_ = -1;
};

}  // namespace hil::harness

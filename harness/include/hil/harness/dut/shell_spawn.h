#pragma once
/// @file
/// Starting a host process (the estimator, the controller) as `/bin/sh -c LINE` in a process
/// group, returning only once the child runs the shell.

#include <string>

#include <sys/types.h>

namespace hil::harness {

/// Where a spawned shell's output goes, and which process group it joins.
struct SpawnTarget {
  pid_t pgid = 0;      ///< the group to join; 0: a new group led by the child
  int stdout_fd = -1;  ///< becomes the child's stdout (-1: /dev/null)
  int stderr_fd = -1;  ///< becomes the child's stderr (-1: /dev/null)
};

/// Marks every descriptor from `first_fd` up close-on-exec (close_range with CLOSE_RANGE_CLOEXEC;
/// a loop up to RLIMIT_NOFILE where the kernel lacks it). Async-signal-safe: for a child between
/// fork and exec, so that the program it runs inherits only its stdin, stdout and stderr, whatever
/// hil or a library opened without O_CLOEXEC (issue 40: navd held hil's capture files open).
void CloseOnExecFrom(int first_fd);

/// Forks, gives the child PR_SET_PDEATHSIG SIGKILL (it dies with the calling thread, which must
/// live as long as the run: hil's main thread; group_reaper.h), puts it in `target.pgid`, gives it
/// stdin from /dev/null and the target's stdout and stderr (and no other descriptor of hil:
/// CloseOnExecFrom), and execs `/bin/sh -c shell_line`.
/// Returns the child's pid once the exec has happened: until then the child is a copy of hil
/// holding every descriptor hil holds (the ptys' slaves too), and a look at the group's open files,
/// as the first host turn takes, would count hil's links as opened by the host (a navd started late
/// was then never waited for). Throws std::runtime_error when the fork or the exec fails (the child
/// is reaped).
pid_t SpawnShell(const std::string& shell_line, const SpawnTarget& target);

}  // namespace hil::harness

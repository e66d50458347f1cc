#include "hil/harness/dut/shell_spawn.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <linux/close_range.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>

namespace hil::harness {
namespace {

// In the child, between fork and exec: async-signal-safe calls only. Sends errno on `report_fd`
// (closed by a successful exec) when the exec fails.
[[noreturn]] void ExecShell(const char* line, const SpawnTarget& t, int report_fd, pid_t parent) {
  // dies with hil's main thread (which spawns every host process and lives as long as the run),
  // even by SIGKILL; a parent already gone before the call left it an orphan: end now
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);
  setpgid(0, t.pgid);
  const int devnull = open("/dev/null", O_RDWR);
  if (devnull >= 0) dup2(devnull, STDIN_FILENO);
  dup2(t.stdout_fd >= 0 ? t.stdout_fd : devnull, STDOUT_FILENO);
  dup2(t.stderr_fd >= 0 ? t.stderr_fd : devnull, STDERR_FILENO);
  if (devnull > STDERR_FILENO) close(devnull);
  CloseOnExecFrom(STDERR_FILENO + 1);  // report_fd too: it is closed by the exec
  execl("/bin/sh", "sh", "-c", line, static_cast<char*>(nullptr));
  const int err = errno;
  [[maybe_unused]] const ssize_t n = write(report_fd, &err, sizeof err);
  _exit(127);
}

}  // namespace

void CloseOnExecFrom(int first_fd) {
  if (syscall(SYS_close_range, first_fd, ~0U, CLOSE_RANGE_CLOEXEC) == 0) return;
  rlimit r{};
  const rlim_t last = getrlimit(RLIMIT_NOFILE, &r) == 0 && r.rlim_cur != RLIM_INFINITY
                          ? r.rlim_cur
                          : static_cast<rlim_t>(65536);
  for (rlim_t fd = static_cast<rlim_t>(first_fd); fd < last; ++fd) {
    const int flags = fcntl(static_cast<int>(fd), F_GETFD);
    if (flags >= 0) fcntl(static_cast<int>(fd), F_SETFD, flags | FD_CLOEXEC);
  }
}

pid_t SpawnShell(const std::string& shell_line, const SpawnTarget& target) {
  int report[2];
  if (pipe2(report, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    const int err = errno;
    close(report[0]);
    close(report[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(err));
  }
  if (pid == 0) ExecShell(shell_line.c_str(), target, report[1], parent);
  setpgid(pid, target.pgid == 0 ? pid : target.pgid);  // either side may run first
  close(report[1]);
  // the exec closes the pipe's write end (end of file); a failed exec sends its errno first
  int err = 0;
  ssize_t n;
  while ((n = read(report[0], &err, sizeof err)) < 0 && errno == EINTR) {
  }
  close(report[0]);
  if (n <= 0) return pid;
  while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
  }
  throw std::runtime_error(std::string("cannot run /bin/sh: ") + std::strerror(err));
}

}  // namespace hil::harness

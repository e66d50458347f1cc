#include "hil/harness/dut/group_reaper.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <string>

#include <sys/prctl.h>
#include <sys/wait.h>

#include "hil/harness/dut/process_group.h"

namespace hil::harness {
namespace {

constexpr int kReaperMaxGroups = 64;  // a run owns one or two groups (estimator, controller)
constexpr int kReaperPipeFd = 3,
              kReaperKeptFd = 4;        // the reaper's descriptors after it closed the others
constexpr int kReaperGoneChecks = 500;  // waits for the killed groups: up to 500 x 10 ms
constexpr long kReaperGoneCheckNs = 10'000'000;

void ReaperSleepNs(long ns) {
  timespec t{0, ns};
  while (nanosleep(&t, &t) != 0 && errno == EINTR) {
  }
}

// The reaper: reads +pgid (watch) and -pgid (release) until the pipe ends, then kills what it
// still watches. A copy of a one-threaded hil (GroupReaper's contract), so it may allocate.
[[noreturn]] void ReaperMain(int read_fd, int keep_fd) {
  setsid();
  prctl(PR_SET_NAME, "hil-reaper");  // its name in ps and top (a copy of hil otherwise)
  for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, SIGTSTP}) signal(s, SIG_IGN);
  const int devnull = open("/dev/null", O_RDWR);
  for (int fd = 0; fd <= 2; ++fd) dup2(devnull, fd);
  // above the two places first: either may hold the other descriptor now
  const int pipe_high = fcntl(read_fd, F_DUPFD, 16);
  const int keep_high = keep_fd >= 0 ? fcntl(keep_fd, F_DUPFD, 16) : -1;
  dup2(pipe_high, kReaperPipeFd);
  if (keep_high >= 0) dup2(keep_high, kReaperKeptFd);
  close_range(keep_high >= 0 ? kReaperKeptFd + 1 : kReaperPipeFd + 1, ~0U, 0);
  pid_t groups[kReaperMaxGroups];
  int n = 0;
  for (;;) {
    int v[16];
    const ssize_t got = read(kReaperPipeFd, v, sizeof v);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    for (ssize_t k = 0; k < got / static_cast<ssize_t>(sizeof(int)); ++k) {
      if (v[k] > 0 && n < kReaperMaxGroups) groups[n++] = v[k];
      for (int i = 0; v[k] < 0 && i < n; ++i) {
        if (groups[i] == -v[k]) groups[i--] = groups[--n];
      }
    }
  }
  for (int i = 0; i < n; ++i) kill(-groups[i], SIGKILL);
  for (int check = 0; check < kReaperGoneChecks; ++check) {
    bool alive = false;
    for (int i = 0; i < n && !alive; ++i) alive = !LiveGroupMembers(groups[i]).empty();
    if (!alive) break;
    for (int i = 0; i < n; ++i) kill(-groups[i], SIGKILL);  // a fork that raced the first kill
    ReaperSleepNs(kReaperGoneCheckNs);
  }
  _exit(0);
}

}  // namespace

GroupReaper::GroupReaper(int keep_fd) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  pid_ = fork();
  if (pid_ < 0) {
    const int err = errno;
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(err));
  }
  if (pid_ == 0) {
    close(fds[1]);
    ReaperMain(fds[0], keep_fd);
  }
  close(fds[0]);
  write_fd_ = fds[1];
}

GroupReaper::~GroupReaper() {
  if (write_fd_ >= 0) close(write_fd_);
  if (pid_ > 0) {
    while (waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
}

void GroupReaper::Send(int value) {
  // 4 bytes: one atomic write (PIPE_BUF); the reaper reads whole values
  while (write(write_fd_, &value, sizeof value) < 0 && errno == EINTR) {
  }
}

void GroupReaper::Watch(pid_t pgid) {
  if (pgid > 0) Send(pgid);
}

void GroupReaper::Release(pid_t pgid) {
  if (pgid > 0) Send(-pgid);
}

}  // namespace hil::harness

#include "hil/harness/dut/controller_process.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <sys/wait.h>

#include "hil/harness/dut/shell_spawn.h"

namespace hil::harness {

ControllerProcess::ControllerProcess(const std::string& command, int pgid,
                                     const std::string& log_path, const std::string& shell_prefix) {
  const int log_fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log_fd < 0)
    throw std::runtime_error("cannot write " + log_path + ": " + std::strerror(errno));
  try {
    pid_ = SpawnShell(shell_prefix + "exec " + command, {pgid, log_fd, log_fd});
  } catch (...) {
    close(log_fd);
    throw;
  }
  close(log_fd);
}

ControllerProcess::~ControllerProcess() { Kill(); }

void ControllerProcess::Reap(int status) {
  reaped_ = true;
  if (killed_) {
    state_ = "killed by hil";
  } else if (WIFEXITED(status)) {
    state_ = "exited with code " + std::to_string(WEXITSTATUS(status));
  } else if (WIFSIGNALED(status)) {
    state_ = "ended by signal " + std::to_string(WTERMSIG(status));
  }
}

bool ControllerProcess::Running() {
  if (reaped_ || pid_ <= 0) return false;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) {
    Reap(status);
    return false;
  }
  return true;
}

void ControllerProcess::Kill() {
  if (!Running()) return;
  killed_ = true;
  kill(pid_, SIGKILL);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  Reap(status);
}

}  // namespace hil::harness

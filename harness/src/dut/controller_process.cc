#include "hil/harness/dut/controller_process.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <sys/wait.h>

namespace hil::harness {

ControllerProcess::ControllerProcess(const std::string& command, int pgid,
                                     const std::string& log_path) {
  const int log_fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log_fd < 0)
    throw std::runtime_error("cannot write " + log_path + ": " + std::strerror(errno));
  pid_ = fork();
  if (pid_ < 0) {
    close(log_fd);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid_ == 0) {
    setpgid(0, pgid);
    dup2(log_fd, STDOUT_FILENO);
    dup2(log_fd, STDERR_FILENO);
    const int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, STDIN_FILENO);
    execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid_, pgid);
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

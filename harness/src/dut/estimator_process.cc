#include "hil/harness/dut/estimator_process.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include <nlohmann/json.hpp>
#include <sys/ioctl.h>
#include <sys/wait.h>

#include "hil/firmware_emu/wall_time.h"
#include "hil/harness/dut/process_group.h"
#include "hil/harness/dut/shell_spawn.h"

namespace hil::harness {
namespace {

// After Stop, the stdout pipe's end is waited for until the reader thread has slept this long
// (wall) in its read of the empty pipe: a process that left the group holds it open. The time the
// reader runs or waits for a CPU, or the pipe holds bytes, does not count: on a loaded machine the
// reader is late, not done, and the lines it has yet to take are part of the run's output.
constexpr Duration kStdoutEndWait = std::chrono::milliseconds(200);
// ... and at most this long (wall) in all: a process outside the group that keeps writing.
constexpr Duration kStdoutEndLimit = std::chrono::seconds(10);

}  // namespace

std::string ShellCommandLine(const std::string& command) {
  const std::size_t first = command.find_first_not_of(" \t");
  if (first == std::string::npos) return command;
  const std::size_t end = command.find_first_of(" \t", first);
  const std::string program = command.substr(first, end - first);
  // a path to a program (not a builtin, keyword or assignment), then plain words
  const bool path =
      program.find('/') != std::string::npos && program.find('=') == std::string::npos;
  const bool plain = command.find_first_of(";&|<>()$`\\\n*?[]{}~#!\"'") == std::string::npos;
  return path && plain ? "exec " + command : command;
}

std::string ExitInfo::Describe() const {
  if (signal != 0)
    return std::string("ended by signal ") + std::to_string(signal) + " (" + strsignal(signal) +
           ")";
  return "exited with code " + std::to_string(exit_code);
}

EstimatorProcess::EstimatorProcess(const std::string& command, const std::string& stderr_path,
                                   const std::string& shell_prefix) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const int err_fd = open(stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (err_fd < 0) {
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error("cannot write " + stderr_path + ": " + std::strerror(errno));
  }
  try {
    // its own process group, so Stop() reaches the shell's children too
    pid_ = SpawnShell(shell_prefix + ShellCommandLine(command), {0, fds[1], err_fd});
  } catch (...) {
    close(fds[0]);
    close(fds[1]);
    close(err_fd);
    throw;
  }
  close(fds[1]);
  close(err_fd);
  stdout_fd_ = fds[0];
  reader_ = std::thread([this] { ReadLoop(); });
}

EstimatorProcess::~EstimatorProcess() {
  Stop(0.5);
  if (reader_.joinable()) reader_.join();
  if (stdout_fd_ >= 0) close(stdout_fd_);
}

void EstimatorProcess::ReadLoop() {
  std::string partial;
  char buf[4096];
  std::vector<OutputLine> got;
  bool skip_to_newline = false;  // the rest of an overlong line
  reader_tid_ = static_cast<int>(gettid());
  for (;;) {
    in_read_ = true;
    const ssize_t n = read(stdout_fd_, buf, sizeof buf);
    in_read_ = false;
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      stdout_closed_ = true;
      break;
    }
    const WallTime now = WallNow();
    output_bytes_ += static_cast<std::uint64_t>(n);
    std::string_view in(buf, static_cast<std::size_t>(n));
    if (skip_to_newline) {
      const std::size_t nl = in.find('\n');
      if (nl == std::string_view::npos) continue;
      in.remove_prefix(nl + 1);
      skip_to_newline = false;
    }
    partial.append(in);
    got.clear();
    std::size_t pos;
    while ((pos = partial.find('\n')) != std::string::npos) {
      got.push_back(MakeLine(partial.substr(0, pos), now));
      partial.erase(0, pos + 1);
    }
    if (partial.size() > kMaxLineBytes) {  // kept cut short; the rest of it is skipped
      got.push_back(MakeLine(partial.substr(0, kMaxLineBytes), now));
      partial.clear();
      skip_to_newline = true;
      ++overlong_lines_;
    }
    if (got.empty()) continue;
    Queue(got, now);
  }
}

OutputLine EstimatorProcess::MakeLine(std::string text, WallTime now) {
  OutputLine l{std::move(text), now, nullptr, nullptr};
  if (scan_solutions_ && !l.text.empty() && l.text.front() == '{') {
    if (auto scan = scanner_.Scan(l.text))
      l.scanned = std::make_shared<const JsonSolutionLine>(std::move(*scan));
  }
  if (!l.scanned && parse_json_ && !l.text.empty() && l.text.front() == '{') {
    l.json = std::make_shared<const nlohmann::json>(nlohmann::json::parse(l.text, nullptr, false));
  }
  return l;
}

void EstimatorProcess::Queue(std::vector<OutputLine>& got, WallTime now) {
  std::vector<OutputLine> used;
  {
    std::lock_guard<std::mutex> lock(mu_);
    for (OutputLine& l : got) {
      if (queued_bytes_ + l.text.size() > kMaxQueuedBytes) {  // the run cannot keep up: dropped
        dropped_bytes_ += l.text.size() + 1;
        continue;
      }
      queued_bytes_ += l.text.size() + 1;
      lines_.push_back(std::move(l));
    }
    last_output_wall_ = now;
    used.swap(used_);
  }
  // `used` frees here, on the thread that allocated its lines, outside the lock
}

void EstimatorProcess::Reap(int status) {
  ExitInfo info;
  info.exited = true;
  if (WIFEXITED(status)) info.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) info.signal = WTERMSIG(status);
  exit_ = info;
}

bool EstimatorProcess::Running() {
  if (exit_) return false;
  int status = 0;
  const pid_t r = waitpid(pid_, &status, WNOHANG);
  if (r == pid_) {
    Reap(status);
    return false;
  }
  return true;
}

std::vector<OutputLine> EstimatorProcess::TakeLines() {
  std::lock_guard<std::mutex> lock(mu_);
  std::vector<OutputLine> out;
  out.swap(lines_);
  queued_bytes_ = 0;
  return out;
}

void EstimatorProcess::ReturnLines(std::vector<OutputLine> used) {
  if (used.empty()) return;
  std::lock_guard<std::mutex> lock(mu_);
  if (used_.empty()) {
    used_.swap(used);  // the caller's vector goes back empty, freed where it was made
  } else {
    for (OutputLine& l : used) used_.push_back(std::move(l));
  }
}

// A zombie of the group (the shell's child, reparented to an init that may reap it seconds later)
// is not alive: it holds no file (not the stdout pipe) and runs no code.
bool EstimatorProcess::GroupAlive() const {
  return pid_ > 0 && kill(-pid_, 0) == 0 && !LiveGroupMembers(pid_).empty();
}

ExitInfo EstimatorProcess::Stop(double grace_s) {
  // the whole process group, even when its leader has already ended: whatever the estimator started
  // (a helper, a shell's children) must not outlive the run, nor keep its stdout pipe open
  const bool was_running = Running();
  if (!was_running && !GroupAlive()) return *exit_;
  kill(-pid_, SIGTERM);
  const WallTime deadline = WallNow() + DurationFromSeconds(grace_s);
  while (WallNow() < deadline) {
    const bool leader = Running();
    if (!leader && !GroupAlive()) break;
    usleep(1000);
  }
  const bool leader_left = Running();
  if (leader_left || GroupAlive()) kill(-pid_, SIGKILL);
  if (leader_left) {
    int status = 0;
    waitpid(pid_, &status, 0);
    Reap(status);
    exit_->killed_by_us = true;
  }
  if (was_running) exit_->exited = false;  // it ended because we asked
  AwaitStdoutEnd();
  return *exit_;
}

bool EstimatorProcess::ReaderWaitsOnEmptyPipe() const {
  int unread = 0;
  if (ioctl(stdout_fd_, FIONREAD, &unread) != 0 || unread > 0) return false;
  // in its read and asleep there: everything written before has been taken (a reader that has
  // just returned from the read runs, or waits for a CPU: state R)
  return in_read_ && reader_tid_ > 0 && ThreadState(getpid(), reader_tid_) == 'S';
}

void EstimatorProcess::AwaitStdoutEnd() {
  // its last lines: the reader thread reads the pipe to its end once no process holds it
  const WallTime start = WallNow();
  WallTime waiting_since = start;
  while (!stdout_closed_) {
    const WallTime now = WallNow();
    if (!ReaderWaitsOnEmptyPipe()) waiting_since = now;
    if (now - waiting_since >= kStdoutEndWait || now - start >= kStdoutEndLimit) return;
    usleep(200);
  }
}

}  // namespace hil::harness

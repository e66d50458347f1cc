#pragma once
/// @file
/// The estimator under test as a child process: started through /bin/sh with its stdout on a pipe
/// (read line by line, each line stamped with its wall-clock arrival), its stderr into a file in
/// the run folder. Crashes and silence are observable; Stop() always ends the process (SIGTERM,
/// then SIGKILL after a grace period).

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "hil/firmware_emu/wall_time.h"
#include "hil/harness/core/json_solution_line.h"

namespace hil::harness {

/// One line the estimator wrote, with its CLOCK_MONOTONIC arrival time.
struct OutputLine {
  std::string text;
  WallTime wall{};
  /// With set_parse_json(true), a line that starts with '{' parsed on the reader thread (possibly
  /// discarded as invalid); otherwise null.
  std::shared_ptr<const nlohmann::json> json;
  /// With set_scan_solutions(true), a line that starts with '{' scanned on the reader thread
  /// (json_solution_line.h), when the scanner answers it (json stays null then); otherwise null.
  std::shared_ptr<const JsonSolutionLine> scanned;
};

/// How the process ended.
struct ExitInfo {
  bool exited = false;        ///< ended by itself (exit or crash) before Stop()
  int exit_code = -1;         ///< when it exited normally
  int signal = 0;             ///< the signal that ended it, if any
  bool killed_by_us = false;  ///< needed SIGKILL after SIGTERM
  std::string Describe() const;
};

/// The shell command line that starts `command`: with `exec ` before it when it is one program
/// run by its path with arguments (no operator, redirection, substitution or glob), so the
/// program replaces the shell: the estimator is the process hil started, its exit status is its
/// own, and a host turn has one process fewer to look at. Anything else is left as it is.
std::string ShellCommandLine(const std::string& command);

class EstimatorProcess {
 public:
  /// A line longer than this is kept cut to it (the rest of it is skipped and counted).
  static constexpr std::size_t kMaxLineBytes = 64 * 1024;
  /// Lines read but not yet taken are held up to this many bytes; more are dropped and counted
  /// (an estimator writing faster than the run takes its lines: RunWatchdog stops such a flood).
  static constexpr std::size_t kMaxQueuedBytes = 64 * 1024 * 1024;

  /// Starts `command` with /bin/sh -c (see ShellCommandLine); stderr goes to `stderr_path`.
  /// @throws std::runtime_error if the process cannot be started.
  /// `shell_prefix`: shell commands run before it in its shell (the preload library's exports
  /// for a run with --lockstep; LockstepHost::ShellExports).
  EstimatorProcess(const std::string& command, const std::string& stderr_path,
                   const std::string& shell_prefix = "");
  ~EstimatorProcess();
  EstimatorProcess(const EstimatorProcess&) = delete;
  EstimatorProcess& operator=(const EstimatorProcess&) = delete;

  /// True while the child runs (reaps it if it has ended).
  bool Running();
  /// Lines received so far (moves them out).
  std::vector<OutputLine> TakeLines();
  /// Gives lines taken back once they are used: the reader thread, which allocated them, frees
  /// them (freed on the caller's thread, each line's memory went back to the reader's malloc
  /// arena under that arena's lock, which the reader held as often as not: seed004 waited for it
  /// about 900 times).
  void ReturnLines(std::vector<OutputLine> used);
  /// CLOCK_MONOTONIC time of the last output line (0 if none yet).
  WallTime last_output_wall() const { return last_output_wall_.load(); }
  /// Stops the process and every process of its group (also when the estimator itself has already
  /// ended): SIGTERM, then SIGKILL after `grace_s`. Idempotent. Returns once the lines it wrote
  /// before it ended have been read from its stdout, however late the machine runs the reader
  /// thread (with the pipe held open by a process that left the group: once the reader has slept
  /// 200 ms on the empty pipe, or after 10 s of its flood).
  ExitInfo Stop(double grace_s = 2.0);
  int pid() const { return pid_; }
  /// Parse JSON lines on the reader thread (see OutputLine::json): the output of a fast
  /// estimator is then decoded beside the run, not in its thread.
  void set_parse_json(bool on) { parse_json_ = on; }
  /// Scan JSON lines on the reader thread first (see OutputLine::scanned); the lines the scanner
  /// does not answer are parsed as set_parse_json says.
  void set_scan_solutions(bool on) { scan_solutions_ = on; }
  /// Bytes read from its stdout so far (all of them, kept or not).
  std::uint64_t output_bytes() const { return output_bytes_.load(); }
  /// Bytes of lines dropped because the queue was full; lines cut at kMaxLineBytes.
  std::uint64_t dropped_bytes() const { return dropped_bytes_.load(); }
  std::uint64_t overlong_lines() const { return overlong_lines_.load(); }

 private:
  void ReadLoop();
  /// Stop's wait for the reader thread to reach the end of the stdout pipe.
  void AwaitStdoutEnd();
  /// Whether the reader thread sleeps in its read of the empty stdout pipe.
  bool ReaderWaitsOnEmptyPipe() const;
  OutputLine MakeLine(std::string text, WallTime now);
  void Queue(std::vector<OutputLine>& got, WallTime now);
  bool GroupAlive() const;
  void Reap(int status);
  int pid_ = -1;
  int stdout_fd_ = -1;
  std::thread reader_;
  std::mutex mu_;
  std::vector<OutputLine> lines_;
  std::vector<OutputLine> used_;  // given back by ReturnLines, freed by the reader thread
  std::size_t queued_bytes_ = 0;  // of lines_ (under mu_)
  std::atomic<std::uint64_t> output_bytes_{0}, dropped_bytes_{0}, overlong_lines_{0};
  std::atomic<WallTime> last_output_wall_{WallTime{}};
  std::atomic<bool> stdout_closed_{false};  // the reader saw end of file
  std::atomic<bool> in_read_{false};        // the reader is in (or about to enter) its read()
  std::atomic<int> reader_tid_{0};
  std::atomic<bool> parse_json_{false};
  std::atomic<bool> scan_solutions_{false};
  JsonSolutionScanner scanner_;  // the reader thread's
  std::optional<ExitInfo> exit_;
};

}  // namespace hil::harness

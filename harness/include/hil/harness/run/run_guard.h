#pragma once
/// @file
/// What keeps a run's end orderly when the outside world misbehaves:
///  - InterruptGuard: while it lives, SIGINT, SIGTERM and SIGHUP to `hil` only set a flag; the run
///    loop sees it, stops the estimator's process group, and writes a report marked incomplete.
///    SIGPIPE and SIGXFSZ are ignored, so a closed pipe or a full file (RLIMIT_FSIZE) turns into a
///    failed write the run can report instead of killing `hil` without a report.
///  - Write failures of the run folder's files (captures, estimate.jsonl) are noted here, so the
///  run
///    can stop with a clear message naming the file.

#include <optional>
#include <string>

namespace hil::harness {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  /// The signal received since the guard was made (0 if none).
  static int received();
};

/// Records that writing `path` failed (the first one is kept).
void NoteWriteFailure(const std::string& path);
/// The first file of the run folder that could not be written, if any.
std::optional<std::string> FirstWriteFailure();
/// Forgets recorded failures (start of a run).
void ClearWriteFailures();

}  // namespace hil::harness

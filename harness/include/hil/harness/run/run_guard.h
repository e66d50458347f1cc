#pragma once
/// @file
/// What keeps a run's end orderly when the outside world misbehaves:
///  - InterruptGuard: while it lives, SIGINT, SIGTERM and SIGHUP to `hil` only set a flag; the run
///    loop sees it, stops the estimator's process group, and writes a report marked incomplete.
///    SIGPIPE and SIGXFSZ are ignored, so a closed pipe or a full file (RLIMIT_FSIZE) turns into a
///    failed write the run can report instead of killing `hil` without a report.
/// (Write failures of the run folder's files are the run's own diagnostics: run_diagnostics.h.)

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

}  // namespace hil::harness

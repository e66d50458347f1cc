#pragma once
/// @file
/// Closed loop: the guidance controller under test as a child process in the estimator's process
/// group (so the virtual gate's host turns wait for both to sleep: the lockstep), started through
/// /bin/sh with stdout and stderr into a file of the run folder. Kill() ends it at once (the
/// `controller_stop` fault), Stop() at the end of the run.

#include <string>

namespace hil::harness {

class ControllerProcess {
 public:
  /// Starts `command` in process group `pgid` (the estimator's). @throws std::runtime_error.
  /// `shell_prefix`: as EstimatorProcess's.
  ControllerProcess(const std::string& command, int pgid, const std::string& log_path,
                    const std::string& shell_prefix = "");
  ~ControllerProcess();
  ControllerProcess(const ControllerProcess&) = delete;
  ControllerProcess& operator=(const ControllerProcess&) = delete;

  /// SIGKILL and reap; idempotent.
  void Kill();
  /// True while the process runs (reaps it once it has ended).
  bool Running();
  int pid() const { return pid_; }
  /// How it ended ("running", "killed by hil", "exited with code N", "ended by signal N").
  std::string Describe() const { return state_; }

 private:
  int pid_ = -1;
  bool reaped_ = false;
  bool killed_ = false;
  std::string state_ = "running";
  void Reap(int status);
};

}  // namespace hil::harness

#pragma once
/// @file
/// What watches a run while the engine executes it (the engine's monitor): after each event
/// time it takes the raw fix, polls the estimator's output, feeds the truth builder, draws the
/// progress line and decides whether the run goes on. The estimator ending is a crash; no output
/// for the silence timeout (real time) is a hang; in virtual mode the gate's waits come here
/// too (OnGateWait): not reading its input for the silence timeout is a hang when the estimator
/// is also silent, a closed port when it still talks.

#include <cstddef>
#include <cstdint>

#include "hil/harness/engine/engine_monitor.h"
#include "hil/harness/run/run_context.h"

namespace hil::harness {

class RunWatchdog final : public EngineMonitor {
 public:
  explicit RunWatchdog(RunContext& ctx) : ctx_(ctx) {}
  void OnDeviceEvents(Time t) override;
  bool KeepGoing(Time t) override;
  /// Closed loop: a `controller_stop` fault kills the controller at the first host turn at or
  /// after its start (the host is idle there: the same point of the run every time).
  void OnHostTurn(Time t) override;
  bool ActsAtTurn(Time t) override;
  /// VirtualGate::WaitStep: false gives the wait (and the run) up.
  bool OnGateWait(std::size_t unread, bool new_wait);
  /// --lockstep: while hil waits for the host's threads to wait again (`busy` of them still
  /// run). Running the silence timeout without any of them waiting is a hang.
  bool OnLockstepWait(std::size_t busy, bool new_wait);

 private:
  /// Kills the controller for the controller_stop faults due at `t`.
  void StopController(Time t);
  /// Whether the estimator still runs, asked of the kernel at most once per millisecond of wall
  /// time (a wait4() per event or wait step costs more than the event in virtual mode).
  bool EstimatorStillRunning();
  RunContext& ctx_;
  WallTime running_checked_{};   // the last wall time the estimator was seen running
  std::size_t wait_unread_ = 0;  // unread bytes at the last gate wait step
  WallTime wait_progress_{};     // wall time the host last read during a gate wait
};

}  // namespace hil::harness

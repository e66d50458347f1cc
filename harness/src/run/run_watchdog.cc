#include "hil/harness/run/run_watchdog.h"

#include <algorithm>
#include <chrono>
#include <string>

namespace hil::harness {

void RunWatchdog::OnDeviceEvents(Time t) {
  ctx_.baseline->Record(t);
  // free-running real time: no host turns
  if (ctx_.pacer->stepping() == Stepping::kFreeRunning) StopController(t);
}

void RunWatchdog::OnHostTurn(Time t) { StopController(t); }

bool RunWatchdog::ActsAtTurn(Time t) {
  if (!ctx_.controller) return false;
  for (const Fault& f : ctx_.scenario.faults.faults) {
    if (f.kind == FaultKind::kControllerStop && f.start <= t && ctx_.controller->Running())
      return true;
  }
  return false;
}

void RunWatchdog::StopController(Time t) {
  if (!ctx_.controller) return;
  const std::vector<Fault>& faults = ctx_.scenario.faults.faults;
  for (std::size_t i = 0; i < faults.size(); ++i) {
    if (faults[i].kind != FaultKind::kControllerStop || faults[i].start > t) continue;
    if (!ctx_.controller->Running()) continue;
    ctx_.controller->Kill();
    ctx_.ControllerGone();
    ctx_.fault_recorder.Note(i, t);
  }
}

bool RunWatchdog::EstimatorStillRunning() {
  const WallTime now = WallNow();
  if (now - running_checked_ < std::chrono::milliseconds(1)) return true;
  running_checked_ = now;
  // a controller that ended on its own: the gate stops waiting for its links
  if (ctx_.controller && !ctx_.controller_gone && !ctx_.controller->Running())
    ctx_.ControllerGone();
  return ctx_.EstimatorRunning();
}

bool RunWatchdog::KeepGoing(Time t) {
  ctx_.t_now = t;
  ctx_.collector->Poll();
  // scores what lies RunScoring::kLateHorizon behind the run (a later solution is not scored)
  ctx_.AskTruth();
  if (ctx_.Interrupted()) return false;
  ctx_.progress->Update(ToSeconds(t), ctx_.scenario.duration_s, ctx_.collector->solutions());
  if (ctx_.options.emulate_only) return true;
  if (!EstimatorStillRunning()) return false;
  if (ctx_.pacer->stepping() != Stepping::kVirtual && ctx_.SilentFor() > ctx_.silence) {
    ctx_.hang = "no output for " + SecondsText(ctx_.silence_s) + " s";
    return false;
  }
  return !ctx_.hang && !ctx_.stop_reason;
}

bool RunWatchdog::OnLockstepWait(std::size_t busy, bool new_wait) {
  if (new_wait || busy < wait_unread_) wait_progress_ = WallNow();
  wait_unread_ = busy;
  ctx_.collector->Poll();
  if (ctx_.Interrupted() || !EstimatorStillRunning()) return false;
  if (WallNow() - wait_progress_ <= ctx_.silence) return true;
  ctx_.hang = std::to_string(busy) + " of its threads did not wait again for " +
              SecondsText(ctx_.silence_s) +
              " s (a busy loop, or a blocking call libhil_lockstep.so does not interpose)";
  return false;
}

bool RunWatchdog::OnGateWait(std::size_t unread, bool new_wait) {
  if (new_wait || unread < wait_unread_) wait_progress_ = WallNow();
  wait_unread_ = unread;
  ctx_.collector->Poll();
  if (ctx_.Interrupted() || !EstimatorStillRunning()) return false;
  if (WallNow() - wait_progress_ <= ctx_.silence) return true;
  const std::string unread_text =
      std::to_string(unread) + " bytes unread for " + SecondsText(ctx_.silence_s) + " s";
  if (ctx_.SilentFor() > ctx_.silence) {
    ctx_.hang = "it stopped reading its input and is silent (" + unread_text + ")";
    return false;
  }
  // still talking but no longer reading: the port was closed by the peer (or is ignored)
  std::string links;
  for (const auto& ports : ctx_.set.endpoints) {
    for (const auto& ep : ports) {
      if (ctx_.HostReads(*ep) && ep->PendingToHost() > 0) links += " " + ep->link_name();
    }
  }
  ctx_.stop_reason = "the estimator stopped reading" + links +
                     " at t = " + SecondsText(ctx_.t_now) + " s (" + unread_text +
                     "): the port was closed by the peer or is no longer read";
  return false;
}

}  // namespace hil::harness

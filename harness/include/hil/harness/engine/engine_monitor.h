#pragma once
/// @file
/// What watches the engine's run, called at every event time (Drake's simulator monitor).

#include "hil/firmware_emu/sim_time.h"

namespace hil::harness {

class EngineMonitor {
 public:
  virtual ~EngineMonitor() = default;
  /// The devices whose event was at `t` have handed over their output; the host's bytes of this
  /// instant are not read yet.
  virtual void OnDeviceEvents(Time t) { (void)t; }
  /// Everything of event time `t` is done: false stops the run early (e.g. the estimator died).
  virtual bool KeepGoing(Time t) = 0;
  /// Host turns (virtual_host_turns.h): a turn at `t` is over (the host was idle and what it
  /// wrote is read); the host is idle now, so what is done to it here is done at a
  /// deterministic point of the run.
  virtual void OnHostTurn(Time t) { (void)t; }
  /// Whether OnHostTurn would act at a turn at `t` (e.g. a controller stop is due): such a turn
  /// is always taken (see VirtualHostTurns).
  virtual bool ActsAtTurn(Time t) {
    (void)t;
    return false;
  }
};

}  // namespace hil::harness

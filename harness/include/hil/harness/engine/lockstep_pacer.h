#pragma once
/// @file
/// Lockstep (pacer.h): a closed loop in real time or scaled mode, as PX4's SITL lockstep with a
/// speed factor. The engine steps as in virtual mode (a gate, host turns, the same decisions in
/// emulated time, so the same bytes both ways), and each action (an event, a host turn, host
/// bytes reaching their device) waits until the wall clock says its time has come; what an event
/// made is written when it is made, at its first byte's time, not byte by byte. A host slower
/// than the pace delays the run instead of changing it.

#include <cstdint>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/engine/virtual_pacer.h"

namespace hil::harness {

class LockstepPacer final : public VirtualPacer {
 public:
  /// `clock`: emulated t = 0's wall instant and the speed factor.
  explicit LockstepPacer(const link::RealtimePacer& clock) : clock_(clock) {}

  Stepping stepping() const override { return Stepping::kLockstep; }
  const link::RealtimePacer* wall_clock() const override { return &clock_; }
  /// The captures' records carry the wall-clock time of their write or read.
  void Start(EngineDevices& devices) override;
  /// Sleeps until the wall-clock time of the step's first action.
  bool Await(const StepTimes& step, DeviceIo& io, DeviceOutput& out) override;
  void EndOfStep(DeviceIo& io) override;
  PaceLateness lateness() const override { return lateness_; }

 private:
  link::RealtimePacer clock_;
  PaceLateness lateness_;
};

}  // namespace hil::harness

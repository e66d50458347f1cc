#pragma once
/// @file
/// Where the engine's step takes the truth the devices sample, chosen once per run: none (devices
/// that read no truth, a replay: a sample holds only its time), integrated with CVODE on the
/// engine's thread (closed loop: the commands steer it; real time), or sampled ahead on a thread
/// of its own (virtual mode and lockstep, open loop: the truth is a function of time alone;
/// truth_ahead.h).

#include <cstddef>
#include <memory>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/truth_sample.h"
#include "hil/harness/engine/pacer.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

class TruthSource {
 public:
  virtual ~TruthSource() = default;
  /// The truth at the event time `t` (times in non-decreasing order); `devices`' next events are
  /// the schedule a sampler ahead predicts from.
  virtual TruthSample Sample(Time t, const std::vector<std::unique_ptr<Device>>& devices) = 0;
  /// devices[d] is served at `t` (before its event).
  virtual void Served(std::size_t d, Time t) { (void)d, (void)t; }
  /// Closed loop: a command the actuators gave the truth.
  virtual void Command(const VehicleCommand& c) { (void)c; }
  /// Whether the last sample is the truth's (a command that acts at its instant re-integrates the
  /// truth, and the sample taken before it is not the truth's any more).
  virtual bool sample_is_truth() const { return true; }
  /// How often the truth was re-integrated from t = 0 for a command that came after it had
  /// passed the command's instant (TruthIntegrator::late_command_restarts).
  virtual long late_command_restarts() const { return 0; }
};

/// The source for `truth` (null: none) and the run's stepping, for `devices` devices.
std::unique_ptr<TruthSource> MakeTruthSource(const truth::TruthConfig* truth, Stepping stepping,
                                             std::size_t devices);

}  // namespace hil::harness

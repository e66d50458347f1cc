#pragma once
/// @file
/// When what the hosts wrote is read: a policy chosen once per run (engine.h).
///
///   VirtualHostTurns  virtual mode and lockstep with a host to wait for: the host's bytes are
///                     read only at host turns, at emulated times fixed by the run itself
///                     (periodic, at the end of a device's answer, at a closed loop's control
///                     ticks), with the host idle (virtual_host_turns.h).
///   NoHostTurns       the hosts are read after every event (real time: their bytes count from
///                     their arrival; virtual mode with no host to wait for: at the event).

#include <cstdint>

#include "hil/harness/engine/device_io.h"
#include "hil/harness/engine/engine_monitor.h"

namespace hil::harness {

class HostTurns {
 public:
  virtual ~HostTurns() = default;
  /// Whether the actuators' bytes wait for the next turn (DeviceIo::ReleaseHeld).
  virtual bool holds_actuator_bytes() const { return false; }
  /// The earliest host action due (host bytes or a bus frame reaching a device, a turn); the
  /// largest time when there is none.
  virtual Time NextAction() const { return Time::max(); }
  /// Before the event at `t_event`: takes the host action due at or before it (and t_end), if
  /// any. True when it took one and the step must be picked again.
  virtual bool BeforeEvent(Time t_event, Time t_end, EngineMonitor& monitor, DeviceIo& io,
                           DeviceOutput& out) = 0;
  /// After the event at `t_event` was served.
  virtual void AfterEvent(Time t_event, DeviceIo& io, DeviceOutput& out) = 0;
  /// After Flush wrote what was left: lets the hosts read it (ClockedHostTurns). False when a wait
  /// was given up.
  virtual bool Drain(DeviceIo& io) {
    (void)io;
    return true;
  }
  /// Closed loop: control ticks that made no turn of their own, their answer in hand.
  virtual std::uint64_t skipped_control_turns() const { return 0; }
};

/// The hosts are read after every event (see the file comment).
class NoHostTurns final : public HostTurns {
 public:
  bool BeforeEvent(Time t_event, Time t_end, EngineMonitor& monitor, DeviceIo& io,
                   DeviceOutput& out) override {
    (void)t_event, (void)t_end, (void)monitor, (void)io, (void)out;
    return false;
  }
  /// Configuration commands from the host reach the device with the pacer's arrival time.
  void AfterEvent(Time t_event, DeviceIo& io, DeviceOutput& out) override {
    io.PollHosts(t_event, out);
  }
};

}  // namespace hil::harness

#pragma once
/// @file
/// Host turns (host_turns.h; virtual mode and lockstep): the bytes a host writes to its devices
/// are read only at host turns, at emulated times fixed by the run itself: every
/// `kHostTurnPeriod` from t = 0, and when the last byte of a device's answer to the host has left
/// its UART. At a turn every byte made so far is written and the gate waits until the host has
/// read all of it and sleeps (VirtualGate::WaitHostIdle). What the host wrote then answers bytes
/// written up to now: it reaches its device when the last of them has left its UART (virtual
/// mode writes bytes when they are made, ahead of their UART times), or at the turn's time if
/// that is later. A configuration dialogue (command, ACK, next command …) thus runs at the pace
/// of the emulated UARTs, and an unsolicited command arrives after the next turn, the same in
/// every run. In open loop, a host whose first turn found every host link held read-only (it
/// cannot write to them: navd opens its devices O_RDONLY unless it configures a receiver) is not
/// waited for at the periodic turns; the turns resume if bytes come from it all the same.
///
/// Closed loop (`control_period` above zero): a turn also at every control tick (every period
/// from the period on): the controller has read everything made before the tick and answered
/// before emulated time passes it (lockstep); its command reaches the actuator at the turn. A
/// tick whose answer is already in hand (host bytes read at an earlier turn wait to reach their
/// device, at or after the tick: a controller answering a GNSS epoch is read at the turn that
/// ends the epoch's last byte, before the tick) makes no turn of its own, unless another turn
/// falls on it or the monitor acts at it; what the host writes meanwhile is read at the next
/// turn. Every tick's turn is taken or skipped the same way in every run. The actuators' replies
/// and status (serial bytes, and CAN frames: the steering ECU's on SocketCAN) are held until the
/// next turn, which writes them with the host asleep; frames on a bus, which the gate cannot see
/// read, are then waited for as well: their echoes back (the host's socket has them too) and the
/// host asleep again. So which status the controller has read when a solution comes is the same
/// in every run.

#include <vector>

#include "hil/harness/engine/host_arrivals.h"
#include "hil/harness/engine/host_turns.h"
#include "hil/harness/engine/virtual_gate.h"

namespace hil::harness {

class VirtualHostTurns final : public HostTurns {
 public:
  /// Virtual mode's regular host turns.
  static constexpr Duration kHostTurnPeriod = std::chrono::seconds(1);

  /// `control_period`: zero in open loop (no control ticks).
  VirtualHostTurns(VirtualGate& gate, Duration control_period);

  bool holds_actuator_bytes() const override { return control_period_ > Duration{}; }
  Time NextAction() const override;
  /// Host bytes arriving, a bus frame arriving, then a host turn, due before (or at) the event.
  bool BeforeEvent(Time t_event, Time t_end, EngineMonitor& monitor, DeviceIo& io,
                   DeviceOutput& out) override;
  /// Nothing: the hosts are read at turns only.
  void AfterEvent(Time t_event, DeviceIo& io, DeviceOutput& out) override {
    (void)t_event, (void)io, (void)out;
  }
  std::uint64_t skipped_control_turns() const override { return skipped_control_turns_; }

 private:
  /// The next host turn.
  Time NextHostTurn() const;
  /// Whether the turn at `t` is a control tick's alone and the host's answer to it is already
  /// queued.
  bool ControlTickAnswered(Time t) const;
  /// A host turn at `t` (every byte written, the host read and asleep); what it wrote is
  /// captured and queued in arrivals_. False when the gate gave up.
  bool HostTurn(Time t, DeviceIo& io);
  /// The emulated time what the host wrote at the turn at `t` arrives at.
  Time ArrivalTime(Time t, DeviceIo& io) const;
  /// Host bytes due by `limit` reach their device, which may answer (sent at once; the host's
  /// next turn is when the answer has left the UART). False when none is due.
  bool DeliverHostBytes(Time limit, DeviceIo& io, DeviceOutput& out);

  VirtualGate& gate_;
  const Duration control_period_;
  Time next_periodic_turn_{};
  Time next_control_turn_{};
  std::vector<Time> answer_turns_;  // host turns at the ends of devices' answers
  HostArrivals arrivals_;  // host bytes and others' frames read at turns, not yet delivered
  std::uint64_t skipped_control_turns_ = 0;
};

}  // namespace hil::harness

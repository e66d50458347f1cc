#include "hil/harness/engine/virtual_host_turns.h"

#include <algorithm>
#include <optional>

namespace hil::harness {

VirtualHostTurns::VirtualHostTurns(VirtualGate& gate, Duration control_period)
    : gate_(gate), control_period_(control_period), next_control_turn_(Time{} + control_period) {}

Time VirtualHostTurns::NextAction() const { return std::min(NextHostTurn(), arrivals_.Next()); }

bool VirtualHostTurns::BeforeEvent(Time t_event, Time t_end, EngineMonitor& monitor, DeviceIo& io,
                                   DeviceOutput& out) {
  const Time limit = std::min(t_event, t_end);
  if (DeliverHostBytes(limit, io, out) || arrivals_.DeliverFrame(limit, io, out)) return true;
  const Time t_turn = NextHostTurn();
  if (t_turn > t_event || t_turn > t_end) return false;
  if (ControlTickAnswered(t_turn) && !monitor.ActsAtTurn(t_turn)) {
    ++skipped_control_turns_;
    while (next_control_turn_ <= t_turn) next_control_turn_ += control_period_;
    return true;
  }
  if (HostTurn(t_turn, io)) {
    monitor.OnHostTurn(t_turn);
  } else {
    io.Refuse();
  }
  return true;
}

Time VirtualHostTurns::NextHostTurn() const {
  Time t = next_periodic_turn_;
  if (control_period_ > Duration{}) t = std::min(t, next_control_turn_);
  for (const Time a : answer_turns_) t = std::min(t, a);
  return t;
}

bool VirtualHostTurns::ControlTickAnswered(Time t) const {
  if (control_period_ == Duration{} || next_control_turn_ != t || next_periodic_turn_ <= t)
    return false;
  if (std::any_of(answer_turns_.begin(), answer_turns_.end(), [t](Time a) { return a <= t; }))
    return false;
  return arrivals_.has_bytes();
}

bool VirtualHostTurns::HostTurn(Time t, DeviceIo& io) {
  while (next_periodic_turn_ <= t) next_periodic_turn_ += kHostTurnPeriod;
  if (control_period_ > Duration{}) {
    while (next_control_turn_ <= t) next_control_turn_ += control_period_;
  }
  std::erase_if(answer_turns_, [t](Time a) { return a <= t; });
  // An open-loop host holding its links read-only has nothing for a turn to read: no wait (each
  // one cost the host's backlog of work, seed004 0.5 s of 2.9). Bytes from it all the same (it
  // opened a link for writing later) end that.
  if (control_period_ == Duration{} && gate_.HostReadsOnly()) {
    if (!io.HostWrote()) return true;
    gate_.NoteHostWrote();
  }
  if (!io.SendAll() || !gate_.WaitHostIdle()) return false;
  // The actuators' replies and status reach the controller now, with the host asleep: which of
  // them it has read when a solution makes it compute a command does not depend on the machine
  // (written when made, a status frame could be read before or after the solution that came
  // meanwhile; guidanced's reset request after an ECU exit then went out one command early or
  // late in some runs).
  if (io.ReleaseHeld() && !io.SendAll()) return false;
  // A bus is no link of the gate (a socket's unread frames cannot be counted from here): the
  // host has taken the frames once its socket has them and it sleeps again. (Written when made,
  // the steering ECU's frames on vcan0 were read before or after a solution as the machine ran
  // guidanced: a stale reset request read after its re-engaging command disengaged the ECU once
  // more, tractor_autosteer_command_loss_socketcan engagements 3, not 2, beside a busy loop.)
  if (io.AwaitReleasedFrames() && !gate_.WaitHostIdle()) return false;
  const Time t_rx = ArrivalTime(t, io);
  arrivals_.ReadHosts(t_rx, io);
  if (io.devices().steering) arrivals_.ReadBus(t_rx, io);  // open-loop runs read the bus as before
  return true;
}

Time VirtualHostTurns::ArrivalTime(Time t, DeviceIo& io) const {
  // What the host wrote may answer any byte it has read (virtual mode writes bytes when they are
  // made, ahead of their UART times): it arrives once the last of them has left its UART. Links
  // the host does not read do not count (paper 003's UWB navd leaves the 9600 Bd GNSS link
  // unread: its NMEA epochs held a controller's commands back by up to 0.66 s).
  Time t_rx = t;
  for (const auto& ports : io.devices().endpoints) {
    for (const auto& ep : ports) {
      if (gate_.Reads(*ep)) t_rx = std::max(t_rx, ep->last_queued_end());
    }
  }
  return t_rx;
}

bool VirtualHostTurns::DeliverHostBytes(Time limit, DeviceIo& io, DeviceOutput& out) {
  const std::optional<HostArrivals::Delivered> h = arrivals_.DeliverBytes(limit, io, out);
  if (!h) return false;
  io.SendAll();
  // the host's next turn: when the answer has left the UART (it is written at once)
  if (h->answered) {
    for (const auto& e : io.devices().endpoints[h->device]) {
      if (e->last_queued_end() > h->t) answer_turns_.push_back(e->last_queued_end());
    }
  }
  return true;
}

}  // namespace hil::harness

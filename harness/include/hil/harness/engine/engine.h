#pragma once
/// @file
/// The one scheduler that owns the clock (order of operations in run.h). It advances emulated
/// time from device event to device event; in real-time/scaled mode a pacing thread of its own
/// (pacing_thread.h) writes each byte and CAN frame at its wall-clock time meanwhile. Byte faults
/// of the timeline are applied to whole messages before they enter a UART queue, so the bytes
/// depend only on the scenario and the seed. It only schedules: what the run does at each event
/// time (watching the estimator, recording the raw fixes) is a SchedulerMonitor's, and files are
/// written elsewhere. A run drives the scenario's emulated devices through it; `hil replay` drives
/// a ReplayDevice.
///
/// Host turns (virtual mode): the bytes a host writes to its devices are read only at host turns,
/// at emulated times fixed by the run itself: every `kHostTurnPeriod` from t = 0, and when the
/// last byte of a device's answer to the host has left its UART. At a turn every byte made so far
/// is written and the gate waits until the host has read all of it and sleeps
/// (VirtualGate::WaitHostIdle). What the host wrote then answers bytes written up to now: it
/// reaches its device when the last of them has left its UART (virtual mode writes bytes when
/// they are made, ahead of their UART times), or at the turn's time if that is later. A
/// configuration dialogue (command, ACK, next command …) thus runs at the pace of the emulated
/// UARTs, and an unsolicited command arrives after the next turn, the same in every run.
/// In open loop, a host whose first turn found every host link held read-only (it cannot write
/// to them: navd opens its devices O_RDONLY unless it configures a receiver) is not waited for at
/// the periodic turns; the turns resume if bytes come from it all the same.

#include <poll.h>

#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/faults/byte_faults.h"
#include "hil/harness/faults/fault_record.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/engine/pacing_thread.h"
#include "hil/harness/engine/truth_ahead.h"
#include "hil/harness/engine/virtual_gate.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

/// What watches a scheduler's run, called at every event time (Drake's simulator monitor).
class SchedulerMonitor {
 public:
  virtual ~SchedulerMonitor() = default;
  /// The devices whose event was at `t` have handed over their output; the host's bytes of this
  /// instant are not read yet.
  virtual void OnDeviceEvents(Time t) { (void)t; }
  /// Everything of event time `t` is done: false stops the run early (e.g. the estimator died).
  virtual bool KeepGoing(Time t) = 0;
  /// Virtual mode: a host turn at `t` is over (the host was idle and what it wrote is read); the
  /// host is idle now, so what is done to it here is done at a deterministic point of the run.
  virtual void OnHostTurn(Time t) { (void)t; }
  /// Whether OnHostTurn would act at a turn at `t` (e.g. a controller stop is due): such a turn
  /// is always taken (see Scheduler::set_control_period).
  virtual bool ActsAtTurn(Time t) {
    (void)t;
    return false;
  }
};

class Scheduler {
 public:
  /// `pacer` null: virtual mode. Events after `t_end` are not served.
  Scheduler(DeviceSet& devices, const link::RealtimePacer* pacer, Time t_end);

  /// The byte faults applied to every message and frame (none when not set).
  void set_byte_faults(ByteFaultInjector* faults) { faults_ = faults; }
  /// Where the faults of the timeline applied here are counted (receiver messages lost to its
  /// transmit buffer in an output overload).
  void set_recorder(FaultRecorder* recorder) { recorder_ = recorder; }

  /// Virtual mode: the gate that keeps the host's links in order (virtual_gate.h); without one
  /// bytes are written as they are made. When the gate gives up a wait the run stops and the bytes
  /// not yet written stay unsent.
  void set_gate(VirtualGate* gate) {
    gate_ = gate;
    writes_ = VirtualWriteQueue(gate, kMaxDeferredBytes);
  }
  /// Virtual mode's regular host turns (see the file comment).
  static constexpr Duration kHostTurnPeriod = std::chrono::seconds(1);
  /// Closed loop (virtual mode): a host turn also at every control tick (every `period` from
  /// `period` on): the controller has read everything made before the tick and answered before
  /// emulated time passes it (lockstep); its command reaches the actuator at the turn. A tick
  /// whose answer is already in hand (host bytes read at an earlier turn wait to reach their
  /// device, at or after the tick: a controller answering a GNSS epoch is read at the turn that
  /// ends the epoch's last byte, before the tick) makes no turn of its own, unless another turn
  /// falls on it or the monitor acts at it; what the host writes meanwhile is read at the next
  /// turn. Every tick's turn is taken or skipped the same way in every run.
  void set_control_period(Duration period) {
    control_period_ = period;
    next_control_turn_ = Time{} + period;
  }
  /// Closed loop in real time or scaled mode (lockstep, as PX4's SITL lockstep with a speed
  /// factor): the scheduler runs as in virtual mode (pacer null, a gate, host turns, the same
  /// decisions in emulated time, so the same bytes both ways), and each action (an event, a host
  /// turn, host bytes reaching their device) waits until `pace` says its wall-clock time has
  /// come; a message is written when it is made, at its first byte's time, not byte by byte.
  /// A host slower than the pace delays the run (lockstep) instead of changing it.
  void set_lockstep_pace(const link::RealtimePacer* pace) { lockstep_pace_ = pace; }
  /// Lockstep: the actions paced, those served more than 1 ms after their wall-clock time, and
  /// the largest delay (wall-clock ns).
  struct PaceLateness {
    std::uint64_t actions = 0, late = 0;
    std::int64_t max_late_ns = 0;
  };
  const PaceLateness& pace_lateness() const { return lateness_; }
  /// Closed loop: the commands the actuators gave the truth so far, in time order (the
  /// evaluation replays them).
  const std::vector<VehicleCommand>& vehicle_commands() const { return vehicle_commands_; }
  /// Closed loop: how often the truth was re-integrated from t = 0 for a command that came after
  /// it had passed the command's instant (TruthIntegrator::late_command_restarts).
  long late_command_restarts() const {
    return integrator_ ? integrator_->late_command_restarts() : 0;
  }
  /// Closed loop (virtual mode): control ticks that made no turn of their own, their answer in
  /// hand (set_control_period).
  std::uint64_t skipped_control_turns() const { return skipped_control_turns_; }

  /// Called with every truth sample the devices are given (e.g. TruthTableBuilder::Offer), in
  /// time order.
  void set_truth_tap(std::function<void(const TruthSample&)> tap) { truth_tap_ = std::move(tap); }

  /// Runs from t = 0 to t_end. The devices sample `truth` (integrated with CVODE); without one
  /// (devices that read no truth, a replay) each event's sample holds only its time.
  void Run(SchedulerMonitor& monitor, const truth::TruthConfig* truth);

  /// Writes the bytes still queued (real time) at their UART times.
  void Flush();
  ~Scheduler();
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;

  /// Frames others put on the CAN bus during the run (the estimator's NMEA 2000 output).
  const std::vector<CanFrame>& bus_frames() const { return bus_frames_; }
  /// Reads what others put on the bus now (also during the drain after Run) and returns them all.
  const std::vector<CanFrame>& PollBus();

 private:
  /// Run's loop; true when it reached t_end, false when the monitor or the gate stopped it.
  bool RunEvents(SchedulerMonitor& monitor, const truth::TruthConfig* truth);
  void Dispatch(std::size_t device, DeviceOutput& out);
  void Serve(Time t_event, const TruthSample& truth, SchedulerMonitor& monitor, DeviceOutput& out);
  /// Real time: starts the pacing thread (pacing_thread.h) and notes the threads' scheduling.
  void StartPacing();
  /// Real time: ends the pacing thread (`drain`: once every byte and frame has left, else at once)
  /// and notes the CPU each real-time thread used meanwhile (DeviceSet::threads).
  void EndPacing(bool drain);
  /// The endpoints' lock while the pacing thread runs (an empty lock otherwise).
  std::unique_lock<std::mutex> LinksLock();
  /// Real time: sleeps towards `t_event` (computed kEventLeadNs ahead) while reading host bytes.
  /// True when it slept and the next action must be picked again.
  bool PaceTowards(Time t_event, DeviceOutput& out);
  /// Lockstep: sleeps until the wall-clock time of the next action at or before `t_event`.
  void PaceLockstep(Time t_event);
  /// Virtual mode: host bytes due, or a host turn due, before (or at) `t_event`. True when it did
  /// one and the next action must be picked again.
  bool HostStep(Time t_event, SchedulerMonitor& monitor, DeviceOutput& out);
  /// Hands the bytes hosts wrote since the last call to their devices, at `t_host` (virtual) or at
  /// their wall arrival time (real time). Returns true when a device queued a reply.
  bool PollHosts(Time t_host, DeviceOutput& out);
  /// One poll() of every endpoint's host side (host_fds_'s revents).
  void PollHostFds();
  /// Whether a host has bytes waiting on an endpoint.
  bool HostWrote();
  /// The truth at `t` from ahead_, after telling it the devices' schedules.
  TruthSample AheadSample(Time t);
  /// Virtual mode: the next host turn.
  Time NextHostTurn() const;
  /// Virtual mode: whether the turn at `t` is a control tick's alone and the host's answer to
  /// it is already queued (set_control_period).
  bool ControlTickAnswered(Time t) const;
  /// Whether devices[d] is the closed loop's actuator (the base or the steering ECU).
  bool Actuator(std::size_t d) const;
  /// Virtual mode: queues the actuators' held bytes for writing (held_).
  void ReleaseHeld();
  /// Bytes a host wrote, read at a host turn, and when they reach their device.
  struct HostBytes {
    Time t{};
    std::size_t device = 0, port = 0;
    std::string bytes;
  };
  /// Virtual mode: a host turn at `t` (every byte written, the host read and asleep); what it
  /// wrote is captured and queued in arrivals_.
  void HostTurn(Time t);
  /// Virtual mode: host bytes reach their device, which may answer.
  void DeliverHostBytes(const HostBytes& h, DeviceOutput& out);
  /// Closed loop on CAN (a steering ECU in the set): the frames others put on the bus since the
  /// last call reach every device (Device::OnBusFrame): in virtual mode queued at a host turn's
  /// time `t_rx` (as host bytes are), in real time delivered at once with their bus time (never
  /// before the last event).
  void RouteBusFrames(Time t_rx, DeviceOutput& out);
  void DeliverBusFrame(Time t, const CanFrame& frame, DeviceOutput& out);

  DeviceSet& set_;
  const link::RealtimePacer* pacer_;
  const link::RealtimePacer* lockstep_pace_ = nullptr;
  PaceLateness lateness_;
  Time t_end_;
  ByteFaultInjector* faults_ = nullptr;
  FaultRecorder* recorder_ = nullptr;
  std::vector<CanFrame> bus_frames_;
  Time t_last_event_{};
  static constexpr std::size_t kMaxDeferredBytes =
      8192;  // virtual mode: bytes the run may hold back
  VirtualWriteQueue writes_{nullptr, kMaxDeferredBytes};
  bool write_refused_ = false;  // the gate gave up a wait
  VirtualGate* gate_ = nullptr;
  Time next_periodic_turn_{};
  Duration control_period_{};  // closed loop: control ticks are host turns (zero: none)
  Time next_control_turn_{};
  std::optional<truth::TruthIntegrator> integrator_;
  /// Virtual mode, open loop: the truth sampled ahead (truth_ahead.h), with each device's next
  /// event and the event it served last, the schedule it predicts from.
  std::optional<TruthAhead> ahead_;
  std::vector<TruthAhead::DeviceSchedule> schedule_;
  std::vector<std::optional<Time>> last_event_;
  std::function<void(const TruthSample&)> truth_tap_;
  std::vector<VehicleCommand> vehicle_commands_;
  std::vector<Time> answer_turns_;  // host turns at the ends of devices' answers
  std::deque<HostBytes> arrivals_;  // read at turns, in time order, not yet delivered
  std::uint64_t skipped_control_turns_ = 0;
  /// Closed loop, virtual mode: the actuators' bytes queued on their links since the last host
  /// turn, written to the controller at the next one.
  struct Held {
    SerialEndpoint* ep;
    std::size_t bytes;
    Time t;
  };
  std::vector<Held> held_;
  /// Real time: this thread's CPU when the pacing began.
  link::ThreadCpuReading events_cpu_start_;
  struct BusArrival {
    Time t{};
    CanFrame frame;
  };
  std::deque<BusArrival> bus_arrivals_;   // virtual mode: others' frames read at turns
  std::size_t bus_routed_ = 0;            // bus_frames_ handed to the devices or queued
  std::vector<pollfd> host_fds_;          // one per serial endpoint, in device and port order
  std::unique_ptr<PacingThread> pacing_;  // real time: writes the bytes and frames
};

}  // namespace hil::harness

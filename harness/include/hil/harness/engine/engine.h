#pragma once
/// @file
/// The one engine that owns the clock (order of operations in run/run.h). It advances emulated
/// time from device event to device event, one step at a time; the step is written once, here
/// and in Engine::RunEvents, whatever the mode. A mode is two strategies chosen once per run:
/// the pacer (pacer.h: free-running virtual time, the wall clock with a speed factor, lockstep)
/// and the host turns (host_turns.h: virtual mode's turns, or the hosts read after every event).
/// It only schedules: what the run does at each event time (watching the estimator, recording
/// the raw fixes) is an EngineMonitor's, and files are written elsewhere. A run drives the
/// scenario's emulated devices through it; `hil replay` drives a ReplayDevice.
///
/// The step (as Drake's Simulator::AdvanceTo; the hosts' input enters between the devices'
/// output and the next step, as MuJoCo's controller between mj_step1 and mj_step2):
///
///     Run(monitor, truth):
///       source ← MakeTruthSource(truth, pacer)         none | integrated | sampled ahead
///       pacer.Start()                                   wall clock: the pacing thread starts
///       loop:
///         t_event ← min over devices of next_event_time; none → done
///         t_action ← min(t_event, t_end, turns.NextAction())
///         if pacer.Await(t_event, t_end, t_action): continue
///             wall clock: woke before t_event − lead, read the hosts; lockstep: slept to t_action
///         if turns.BeforeEvent(t_event): stop if the gate gave up, else continue
///             host bytes or a bus frame reaching its device, or a host turn, due first
///         if t_event > t_end: done
///         x ← source.Sample(t_event)                    the state at t_event
///         for each device d due at t_event:
///           d.OnEvent(x) → output; a vehicle command → source.Command, vehicle_commands
///           io.Dispatch(d): byte faults, UART queues, the pacer's write path
///         monitor.OnDeviceEvents(t_event)
///         turns.AfterEvent(t_event)                     no turns: the hosts' bytes read now
///         io.PollBus(); pacer.RouteBusFrames()          wall clock: others' frames reach devices
///         if source.sample_is_truth(): tap(x)
///         pacer.EndOfStep()                             lockstep: what the event made leaves now
///         stop if the gate gave up or not monitor.KeepGoing(t_event)
///     Flush(): held actuator bytes released; pacer.Flush() (every byte still queued leaves);
///              turns.Drain() (programs on hil's clock: a last turn reads it)

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "hil/harness/engine/device_io.h"
#include "hil/harness/engine/engine_devices.h"
#include "hil/harness/engine/engine_monitor.h"
#include "hil/harness/engine/host_turns.h"
#include "hil/harness/engine/pacer.h"
#include "hil/harness/engine/truth_source.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

class Engine {
 public:
  /// Events after `t_end` are not served. `pacer` outlives the engine.
  Engine(EngineDevices devices, Pacer& pacer, std::unique_ptr<HostTurns> turns, Time t_end);
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  /// The byte faults applied to every message and frame (none when not set).
  void set_byte_faults(ByteFaultInjector* faults) { io_.set_byte_faults(faults); }
  /// Where the faults of the timeline applied here are counted.
  void set_recorder(FaultRecorder* recorder) { io_.set_recorder(recorder); }
  /// Called with every truth sample the devices are given (e.g. TruthTableBuilder::Offer), in
  /// time order.
  void set_truth_tap(std::function<void(const TruthSample&)> tap) { truth_tap_ = std::move(tap); }
  /// Closed loop: called with every command the actuators give the truth, in time order, and
  /// whether the truth had passed its instant (late: it re-integrates, late_command_restarts());
  /// e.g. TruthTableBuilder::Command. None are kept here.
  void set_command_tap(std::function<void(const VehicleCommand&, bool late)> tap) {
    command_tap_ = std::move(tap);
  }

  /// Runs from t = 0 to t_end. The devices sample `truth` (integrated with CVODE); without one
  /// (devices that read no truth, a replay) each event's sample holds only its time.
  void Run(EngineMonitor& monitor, const truth::TruthConfig* truth);
  /// Writes the bytes still queued (real time: at their UART times).
  void Flush();

  /// Closed loop: how often the truth was re-integrated from t = 0 for a late command.
  long late_command_restarts() const { return truth_->late_command_restarts(); }
  /// Closed loop with host turns: control ticks that made no turn of their own.
  std::uint64_t skipped_control_turns() const { return turns_->skipped_control_turns(); }
  /// The estimator's NMEA 2000 output is read off the bus (TakeBusFramesForCollector): the frames
  /// others put on it are kept until it has taken them.
  void KeepBusFramesForCollector() { io_.KeepBusFramesForCollector(); }
  /// Reads what others put on the bus now (also during the drain after Run) and returns the
  /// frames not returned before.
  std::vector<CanFrame> TakeBusFramesForCollector() {
    io_.PollBus();
    return io_.TakeUncollected();
  }

 private:
  /// Run's loop; true when it reached t_end, false when the monitor or the gate stopped it.
  bool RunEvents(EngineMonitor& monitor, const truth::TruthConfig* truth);
  /// The earliest next event of the devices (none without devices).
  std::optional<Time> NextEvent() const;
  /// The devices due at `t_event` sample `x`; their output goes out, the hosts are read. True
  /// when one of their commands came late (the truth re-integrates).
  bool Serve(Time t_event, const TruthSample& x, EngineMonitor& monitor, DeviceOutput& out);

  Pacer& pacer_;
  std::unique_ptr<HostTurns> turns_;
  DeviceIo io_;
  Time t_end_;
  std::unique_ptr<TruthSource> truth_;
  std::function<void(const TruthSample&)> truth_tap_ = [](const TruthSample&) {};
  std::function<void(const VehicleCommand&, bool)> command_tap_ = [](const VehicleCommand&, bool) {
  };
};

}  // namespace hil::harness

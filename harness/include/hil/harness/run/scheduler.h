#pragma once
/// @file
/// The one scheduler that owns the clock (order of operations in run.h). It advances emulated
/// time from device event to device event; in real-time/scaled mode it also writes each byte and
/// CAN frame at its wall-clock time. Byte faults of the timeline are applied to whole messages
/// before they enter a UART queue, so the bytes depend only on the scenario and the seed. It only
/// schedules: what the run does at each event time (watching the estimator, recording the raw
/// fixes) is a SchedulerMonitor's, and files are written elsewhere.
/// A run drives the scenario's emulated devices through it; `hil replay` drives a ReplayDevice.

#include <poll.h>

#include <optional>
#include <vector>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/faults/byte_faults.h"
#include "hil/harness/faults/fault_record.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/run/virtual_gate.h"
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
  void set_gate(VirtualGate* gate) { writes_ = VirtualWriteQueue(gate, kMaxDeferredBytes); }

  /// Runs from t = 0 to t_end. The devices sample `truth` (integrated with CVODE); without one
  /// (devices that read no truth, a replay) each event's sample holds only its time.
  void Run(SchedulerMonitor& monitor, const truth::TruthConfig* truth);

  /// Writes the bytes still queued (real time) at their UART times.
  void Flush();

  /// Frames others put on the CAN bus during the run (the estimator's NMEA 2000 output).
  const std::vector<CanFrame>& bus_frames() const { return bus_frames_; }
  /// Reads what others put on the bus now (also during the drain after Run) and returns them all.
  const std::vector<CanFrame>& PollBus();

 private:
  void Dispatch(std::size_t device, DeviceOutput& out);
  void Serve(Time t_event, const TruthSample& truth, SchedulerMonitor& monitor, DeviceOutput& out);
  /// Real time: writes the byte or frame due before `t_event`, or sleeps towards it while
  /// reading host bytes. True when it did something and the next action must be picked again.
  bool PaceTowards(Time t_event, DeviceOutput& out);
  /// Hands the bytes hosts wrote since the last call to their devices, at `t_host` (virtual) or at
  /// their wall arrival time (real time). Returns true when a device queued a reply.
  bool PollHosts(Time t_host, DeviceOutput& out);

  DeviceSet& set_;
  const link::RealtimePacer* pacer_;
  Time t_end_;
  ByteFaultInjector* faults_ = nullptr;
  FaultRecorder* recorder_ = nullptr;
  std::vector<CanFrame> bus_frames_;
  Time t_last_event_{};
  static constexpr std::size_t kMaxDeferredBytes =
      8192;  // virtual mode: bytes the run may hold back
  VirtualWriteQueue writes_{nullptr, kMaxDeferredBytes};
  bool write_refused_ = false;    // the gate gave up a wait
  std::vector<pollfd> host_fds_;  // one per serial endpoint, in device and port order
};

}  // namespace hil::harness

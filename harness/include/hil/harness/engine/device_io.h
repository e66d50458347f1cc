#pragma once
/// @file
/// The devices' side of the engine's step: a device's output goes to its links (through the byte
/// faults of the timeline and the pacer's write path), what the hosts wrote and what others put
/// on the CAN bus goes to the devices. Byte faults are applied to whole messages before they
/// enter a UART queue, so the bytes depend only on the scenario and the seed.

#include <poll.h>

#include <cstddef>
#include <optional>
#include <vector>

#include "hil/harness/engine/engine_devices.h"
#include "hil/harness/engine/pacer.h"
#include "hil/harness/faults/byte_faults.h"
#include "hil/harness/faults/fault_record.h"

namespace hil::harness {

class DeviceIo {
 public:
  /// `hold_actuators`: the actuators' bytes and CAN frames wait for the next host turn
  /// (ReleaseHeld).
  DeviceIo(EngineDevices devices, Pacer& pacer, bool hold_actuators);

  EngineDevices& devices() { return devices_; }
  const EngineDevices& devices() const { return devices_; }
  Pacer& pacer() { return pacer_; }
  /// The byte faults applied to every message and frame (none when not set).
  void set_byte_faults(ByteFaultInjector* faults) { faults_ = faults; }
  /// Where the faults applied here are counted (receiver messages lost to its transmit buffer in
  /// an output overload).
  void set_recorder(FaultRecorder* recorder) { recorder_ = recorder; }

  /// Queues devices[d]'s output on its links and the bus, and sends what may go now.
  void Dispatch(std::size_t d, DeviceOutput& out);
  /// Hands the bytes hosts wrote since the last call to their devices, at the pacer's
  /// HostBytesTime(t_host). Returns true when a device queued a reply.
  bool PollHosts(Time t_host, DeviceOutput& out);
  /// One poll() of every endpoint's host side (host_fds()'s revents).
  void PollHostFds();
  /// One per serial endpoint, in device and port order, as the last PollHostFds() left them.
  const std::vector<pollfd>& host_fds() const { return host_fds_; }
  /// Whether a host has bytes waiting on an endpoint.
  bool HostWrote();
  /// Reads what others put on the bus now (into bus_frames()).
  void PollBus();
  /// Frames others put on the bus (the estimator's NMEA 2000 output, a controller's commands) not
  /// yet taken by every reader: the devices (TakeUnrouted) and, once it is kept for it
  /// (KeepBusFramesForCollector), the estimator's output reader (TakeUncollected). A frame every
  /// reader has taken is dropped, so that the list does not grow with the run (issue 40).
  std::vector<CanFrame>& bus_frames() { return bus_frames_; }
  /// The bus frames not handed to the devices yet (marked handed).
  std::vector<CanFrame> TakeUnrouted();
  /// From now on the bus frames are kept until TakeUncollected has returned them too.
  void KeepBusFramesForCollector() { bus_collected_ = 0; }
  /// The bus frames not returned by the last call (the estimator's NMEA 2000 output reader).
  std::vector<CanFrame> TakeUncollected();
  /// A frame from the bus reaches every device at `t`.
  void DeliverBusFrame(Time t, const CanFrame& frame, DeviceOutput& out);
  /// Queues the actuators' held bytes for writing (SendAll writes them) and puts their held CAN
  /// frames on the bus; false when none were held.
  bool ReleaseHeld();
  /// After ReleaseHeld put frames on the bus: waits until the kernel has handed them to every
  /// socket on it (CanEndpoint::AwaitEchoes), so that a host reading the bus is awake with them
  /// or has read them. False (no wait) when no frames were released since the last call.
  bool AwaitReleasedFrames();
  /// Writes everything queued now unless the gate gave up already; false once it has.
  bool SendAll();
  /// The gate gave up a wait (or a host turn did): the run stops, the bytes not written stay.
  bool refused() const { return refused_; }
  void Refuse() { refused_ = true; }
  /// The latest event time the devices were served at.
  Time t_last_event() const { return t_last_event_; }
  void set_t_last_event(Time t) { t_last_event_ = t; }

 private:
  bool Actuator(std::size_t d) const;
  void QueueMessage(std::size_t d, SerialEndpoint& ep, const SerialMessage& m);

  EngineDevices devices_;
  Pacer& pacer_;
  const bool hold_actuators_;
  ByteFaultInjector* faults_ = nullptr;
  FaultRecorder* recorder_ = nullptr;
  bool refused_ = false;
  Time t_last_event_{};
  /// Drops the frames of bus_frames_ every reader has taken.
  void DropTakenBusFrames();

  std::vector<CanFrame> bus_frames_;
  std::size_t bus_routed_ = 0;                // bus_frames_ handed to the devices or queued
  std::optional<std::size_t> bus_collected_;  // bus_frames_ returned by TakeUncollected
  std::vector<pollfd> host_fds_;              // one per serial endpoint, in device and port order
  /// The actuators' bytes queued on their links since the last host turn.
  struct Held {
    SerialEndpoint* ep;
    std::size_t bytes;
    Time t;
  };
  std::vector<Held> held_;
  std::vector<CanFrame> held_frames_;   // the actuators' frames made since the last host turn
  bool frames_released_ = false;        // ReleaseHeld put frames on the bus, not yet awaited
  std::vector<SerialMessage> carried_;  // Dispatch's scratch: a message after the byte faults
};

}  // namespace hil::harness

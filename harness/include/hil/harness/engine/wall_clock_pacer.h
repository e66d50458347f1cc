#pragma once
/// @file
/// Real time or scaled (pacer.h): emulated time held to the wall clock with a speed factor. The
/// engine's thread computes each event kEventLead before its wall-clock time and queues its
/// bytes and frames; a pacing thread of its own (pacing_thread.h) writes each at its time. Host
/// bytes are read when they arrive (within kHostPollPeriod) and count from their arrival, not
/// before the last event computed; frames on the bus reach the devices with their bus time.

#include <cstdint>
#include <memory>
#include <optional>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/engine/pacer.h"
#include "hil/harness/engine/pacing_thread.h"

namespace hil::harness {

class WallClockPacer final : public Pacer {
 public:
  /// How long (wall) the event thread sleeps at most before it looks for host bytes again.
  static constexpr Duration kHostPollPeriod = std::chrono::milliseconds(1);
  /// How long (wall) before its time an event is computed, so that its bytes wait in their queues
  /// when the pacing thread is due to write them (a host command read meanwhile counts from that
  /// event's time on: it takes effect at most this much later than it arrived).
  static constexpr Duration kEventLead = std::chrono::milliseconds(5);

  /// `clock`: emulated t = 0's wall instant, the speed factor, and whether the pacing thread
  /// asks for SCHED_FIFO.
  explicit WallClockPacer(const link::RealtimePacer& clock) : clock_(clock) {}
  ~WallClockPacer() override;

  Stepping stepping() const override { return Stepping::kFreeRunning; }
  const link::RealtimePacer* wall_clock() const override { return &clock_; }
  void Start(EngineDevices& devices) override;
  void End(bool drain) override;
  PacingThreads threads() const override { return threads_; }
  std::unique_lock<std::mutex> LinksLock() override;

  /// Sleeps towards the step's event while reading host bytes.
  bool Await(const StepTimes& step, DeviceIo& io, DeviceOutput& out) override;
  /// When the event thread wakes next while it waits for `t_event` at wall instant `now`;
  /// none: the event is due now (or lies after `t_end`), compute it.
  std::optional<WallTime> Wake(Time t_event, Time t_end, WallTime now) const;

  /// The pacing thread writes what the endpoints queue.
  void Queued(SerialEndpoint& ep, std::size_t bytes, Time t_ready) override {
    (void)ep, (void)bytes, (void)t_ready;
  }
  bool Send(CanEndpoint* can, bool write, std::unique_lock<std::mutex>& lock) override;
  /// Every byte and frame still queued leaves at its time; the bus's last echoes are read.
  bool Flush(DeviceIo& io) override;

  Time HostBytesTime(Time t_host, Time t_last_event) const override;
  /// The emulated time of wall instant `now`, not before `t_last_event`.
  Time ArrivalTime(WallTime now, Time t_last_event) const;
  bool host_bytes_virtual() const override { return false; }
  const link::RealtimePacer* bus_stamp_clock() const override { return &clock_; }
  Time BusTime(Time t_last_event) const override;
  void RouteBusFrames(DeviceIo& io, DeviceOutput& out) override;

 private:
  link::RealtimePacer clock_;
  PacingThreads threads_;
  link::ThreadCpuReading events_cpu_start_;  // this thread's CPU when the pacing began
  std::unique_ptr<PacingThread> pacing_;     // between Start and End
};

}  // namespace hil::harness

#pragma once
/// @file
/// Real time: the thread that writes every serial byte and CAN frame at its wall-clock time, and
/// nothing else. The run's event thread (device events, truth samples, host commands, the
/// estimator's output) queues bytes and frames ahead of their times and never paces; so a byte is
/// late only by what the kernel gives this thread, not by the work of an event that happened to be
/// due at the same time (issue 15.10). The thread asks SCHED_FIFO above the event thread and a
/// 1 ns timer slack for itself and reports what it really got.
///
/// Every endpoint access, from either thread, holds links_mutex(): the event thread holds it only
/// to queue, to read host bytes and to poll the bus (microseconds), this thread only to select and
/// write one byte or frame.

#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/links/can_endpoint.h"
#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {

class PacingThread {
 public:
  /// SCHED_FIFO priority of the pacing thread (the event thread asks 50).
  static constexpr int kPriority = 60;

  /// Starts the thread. `can` may be null.
  PacingThread(std::vector<SerialEndpoint*> serial, CanEndpoint* can,
               const link::RealtimePacer& pacer);
  /// Stops the thread (what is still queued stays queued).
  ~PacingThread();
  /// The same, keeping the object (usage() is then known).
  void Stop();
  PacingThread(const PacingThread&) = delete;
  PacingThread& operator=(const PacingThread&) = delete;

  /// The lock every access to the endpoints holds.
  std::mutex& links_mutex() { return mutex_; }
  /// Something was queued (call after releasing links_mutex()).
  void Wake() { cv_.notify_one(); }
  /// Waits until every queued byte and frame has left, then stops the thread.
  void Drain();
  /// The pacing thread's scheduling as the kernel reported it once it had asked for it.
  link::ThreadSchedule schedule();
  /// The CPU the thread used from its start to its end (after Drain() or the destructor's stop;
  /// empty before).
  std::optional<link::ThreadUsage> usage() const { return usage_; }

 private:
  void Loop();
  /// The endpoint (or the CAN bus: index -1) with the earliest byte or frame; false if none.
  bool Earliest(int& serial_index, Time& t) const;

  std::vector<SerialEndpoint*> serial_;
  CanEndpoint* can_;
  const link::RealtimePacer& pacer_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool stop_ = false, drain_ = false, started_ = false;
  link::ThreadSchedule schedule_;
  std::optional<link::ThreadUsage> usage_;  // written by the thread as it ends
  std::thread thread_;
};

}  // namespace hil::harness

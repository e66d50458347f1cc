#pragma once
/// @file
/// Virtual mode, open loop: the truth integrated on a thread of its own, ahead of the devices.
///
/// The open-loop truth is a function of time alone: TruthIntegrator takes its steps whatever times
/// it is asked for (CV_ONE_STEP towards the next time event, never towards a request) and
/// interpolates a request in the step that covers it, so the sample at t is the same bits from
/// any integrator that is asked for t after earlier times only. The engine tells TruthAhead,
/// at every event, when each device's next event is and how far its last one lay before it
/// (Plan); the worker thread samples the times that schedule predicts (every device's next event
/// and its period's multiples after it, up to `kAheadEvents` events ahead) while the main thread
/// runs the devices. Sample(t) takes the worker's sample for t, waits for it if the worker is at
/// it, and computes it on the worker's integrator itself if the worker is behind and idle (a
/// loaded machine did not run it); a time the worker passed without sampling it (a host changed a
/// device's rate) comes from a second integrator on the calling thread, which catches up from its
/// own last time. Either way the sample is the one TruthIntegrator::Sample(t) gives in a single
/// sequence of requests.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "hil/firmware_emu/truth_sample.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

class TruthAhead {
 public:
  /// One device's schedule: its next event, and the time from its last event to that one (zero:
  /// not known yet, only the next event is predicted).
  struct DeviceSchedule {
    Time next{};
    Duration period{};
  };

  explicit TruthAhead(const truth::TruthConfig& config);
  ~TruthAhead();
  TruthAhead(const TruthAhead&) = delete;
  TruthAhead& operator=(const TruthAhead&) = delete;

  /// The devices' schedules now (called before every Sample; only a change wakes the worker).
  void Plan(const std::vector<DeviceSchedule>& schedule);
  /// The truth at `t` (times asked in non-decreasing order). Throws what the integrator threw.
  TruthSample Sample(Time t);

  /// How many Sample() calls the worker answered, how many the caller computed on the worker's
  /// integrator (the worker was behind), and how many on its own (the worker was past them).
  struct Counts {
    std::size_t hits = 0, taken = 0, misses = 0;
  };
  Counts counts();
  /// The worker's samples not taken yet.
  std::size_t ready();

  /// The worker stays at most this many predicted events ahead of the last time asked for.
  static constexpr std::size_t kAheadEvents = 256;

 private:
  void Work();
  /// The earliest predicted time after the worker's last one (lock held), or none.
  std::optional<Time> NextPredicted() const;
  /// Whether the worker has a time to sample now (lock held).
  bool HasWork();
  /// Samples t on the worker's integrator with the lock released meanwhile (held on entry and
  /// return); none when it threw (kept in worker_error_).
  std::optional<TruthSample> SampleWorkerTruth(Time t, std::unique_lock<std::mutex>& lock);
  /// Sample(t) on the worker's integrator, on the calling thread (lock held, released on return).
  TruthSample SampleInPlace(Time t, std::unique_lock<std::mutex>& lock);
  /// Releases the lock, waking the sleeping worker if it has work now.
  void WakeWorkerIfDue(std::unique_lock<std::mutex>& lock);

  truth::TruthConfig config_;
  truth::TruthIntegrator worker_truth_;
  std::optional<truth::TruthIntegrator> own_truth_;  // the misses, on the calling thread

  std::mutex mu_;
  std::condition_variable worker_cv_, caller_cv_;
  std::vector<DeviceSchedule> plan_;
  std::deque<TruthSample> ready_;   // the worker's samples, in time order
  std::optional<Time> working_on_;  // the time the worker is sampling now
  std::optional<Time> last_done_;   // the worker's last sampled time
  std::exception_ptr worker_error_;
  bool stop_ = false;
  bool worker_asleep_ = false;
  bool filling_ = true;
  Counts counts_;
  std::thread worker_;  // last: started once the rest exists
};

}  // namespace hil::harness

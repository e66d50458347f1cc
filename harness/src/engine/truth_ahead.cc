#include "hil/harness/engine/truth_ahead.h"

#include <algorithm>

namespace hil::harness {

TruthAhead::TruthAhead(const truth::TruthConfig& config)
    : config_(config), worker_truth_(config), worker_([this] { Work(); }) {}

TruthAhead::~TruthAhead() {
  {
    const std::lock_guard<std::mutex> lock(mu_);
    stop_ = true;
  }
  worker_cv_.notify_all();
  worker_.join();
}

void TruthAhead::Plan(const std::vector<DeviceSchedule>& schedule) {
  {
    const std::lock_guard<std::mutex> lock(mu_);
    const bool same = std::equal(schedule.begin(), schedule.end(), plan_.begin(), plan_.end(),
                                 [](const DeviceSchedule& a, const DeviceSchedule& b) {
                                   return a.next == b.next && a.period == b.period;
                                 });
    if (same) return;
    plan_ = schedule;
    if (!worker_asleep_ || !HasWork()) return;
  }
  worker_cv_.notify_one();
}

TruthAhead::Counts TruthAhead::counts() {
  const std::lock_guard<std::mutex> lock(mu_);
  return counts_;
}

std::size_t TruthAhead::ready() {
  const std::lock_guard<std::mutex> lock(mu_);
  return ready_.size();
}

bool TruthAhead::HasWork() {
  // hysteresis: a full worker sleeps until half its samples are taken (one wake-up per
  // kAheadEvents / 2 samples, not one per sample)
  if (ready_.size() >= kAheadEvents) filling_ = false;
  if (!filling_ && ready_.size() <= kAheadEvents / 2) filling_ = true;
  return filling_ && NextPredicted().has_value();
}

std::optional<Time> TruthAhead::NextPredicted() const {
  std::optional<Time> best;
  // after the worker's last time; before its first, from t = 0 on (t = 0 included)
  const Time after = last_done_.value_or(Time{});
  const bool strict = last_done_.has_value();
  for (const DeviceSchedule& d : plan_) {
    Time t = d.next;
    const bool early = strict ? t <= after : t < after;
    if (early) {
      if (d.period <= Duration{0}) continue;
      // the first of next + j·period after `after` (or at it)
      const auto j = (after - t) / d.period;
      t += d.period * j;
      if (strict ? t <= after : t < after) t += d.period;
    }
    if (!best || t < *best) best = t;
  }
  return best;
}

std::optional<TruthSample> TruthAhead::SampleWorkerTruth(Time t,
                                                         std::unique_lock<std::mutex>& lock) {
  working_on_ = t;
  lock.unlock();
  std::optional<TruthSample> s;
  std::exception_ptr error;
  try {
    s = worker_truth_.Sample(t);
  } catch (...) {
    error = std::current_exception();
  }
  lock.lock();
  working_on_.reset();
  if (error) {
    worker_error_ = error;  // the caller computes from here on (and meets it too)
    return std::nullopt;
  }
  last_done_ = t;
  return s;
}

void TruthAhead::Work() {
  std::unique_lock<std::mutex> lock(mu_);
  for (;;) {
    worker_asleep_ = true;
    // not while the caller samples on this integrator itself (SampleInPlace)
    worker_cv_.wait(lock, [&] { return stop_ || (!working_on_ && HasWork()); });
    worker_asleep_ = false;
    if (stop_) return;
    const std::optional<TruthSample> s = SampleWorkerTruth(*NextPredicted(), lock);
    if (s) ready_.push_back(*s);
    caller_cv_.notify_all();
    if (!s) return;
  }
}

TruthSample TruthAhead::Sample(Time t) {
  {
    std::unique_lock<std::mutex> lock(mu_);
    for (;;) {
      while (!ready_.empty() && ready_.front().t < t) ready_.pop_front();  // predicted, not asked
      if (!ready_.empty()) {
        if (ready_.front().t != t) break;  // the worker is past t without it: a miss
        TruthSample s = ready_.front();
        ready_.pop_front();
        ++counts_.hits;
        WakeWorkerIfDue(lock);
        return s;
      }
      if (worker_error_) break;
      if (!working_on_) return SampleInPlace(t, lock);
      if (*working_on_ > t) break;  // it is past t: a miss
      caller_cv_.wait(lock);        // it is at t (or before): one sample away
    }
    ++counts_.misses;
  }
  if (!own_truth_) own_truth_.emplace(config_);
  return own_truth_->Sample(t);
}

TruthSample TruthAhead::SampleInPlace(Time t, std::unique_lock<std::mutex>& lock) {
  // The worker is behind and idle (a loaded machine did not run it): the caller takes its
  // integrator for t rather than waiting for the worker to be scheduled; t is after its last
  // time, so the samples stay the same bits.
  ++counts_.taken;
  const std::optional<TruthSample> s = SampleWorkerTruth(t, lock);
  if (!s) std::rethrow_exception(worker_error_);
  WakeWorkerIfDue(lock);
  return *s;
}

void TruthAhead::WakeWorkerIfDue(std::unique_lock<std::mutex>& lock) {
  const bool wake = worker_asleep_ && HasWork();
  lock.unlock();
  if (wake) worker_cv_.notify_one();
}

}  // namespace hil::harness

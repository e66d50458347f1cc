#include "hil/harness/core/truth_table.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace hil::harness {

namespace {

void Replay(truth::TruthIntegrator& truth, const std::vector<VehicleCommand>& commands) {
  for (const VehicleCommand& c : commands) truth.SetCommand(c.t, c.speed_mps, c.steer_or_yaw_rate);
}

}  // namespace

TruthTable::TruthTable(const truth::TruthConfig& config, std::vector<Time> times,
                       const std::vector<VehicleCommand>& commands)
    : times_(std::move(times)), frame_(config.origin) {
  std::erase_if(times_, [](Time t) { return t < Time{}; });
  std::sort(times_.begin(), times_.end());
  times_.erase(std::unique(times_.begin(), times_.end()), times_.end());
  samples_.reserve(times_.size());
  truth::TruthIntegrator truth(config);
  Replay(truth, commands);
  for (const Time t : times_) samples_.push_back(truth.Sample(t));
}

TruthTable::TruthTable(const truth::TruthConfig& config, std::vector<Time> times,
                       std::vector<TruthSample> samples)
    : times_(std::move(times)), samples_(std::move(samples)), frame_(config.origin) {}

bool TruthTable::Has(Time t) const { return std::binary_search(times_.begin(), times_.end(), t); }

const TruthSample& TruthTable::At(Time t) const {
  const auto it = std::lower_bound(times_.begin(), times_.end(), t);
  if (it == times_.end() || *it != t)
    throw std::out_of_range("truth table: no sample at the time asked");
  return samples_[static_cast<std::size_t>(it - times_.begin())];
}

TruthTableBuilder::TruthTableBuilder(const truth::TruthConfig& config)
    : config_(config), worker_([this] { Work(); }) {}

TruthTableBuilder::~TruthTableBuilder() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    finishing_ = true;
  }
  cv_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void TruthTableBuilder::Ask(const std::vector<Time>& times) {
  std::lock_guard<std::mutex> lock(mu_);
  for (const Time t : times) {
    if (t < Time{}) continue;
    if (started_ && t < position_)
      late_.push_back(t);
    else
      asked_.push(t);
  }
}

void TruthTableBuilder::Advance(Time t) {
  if (caller_watermark_ && t <= *caller_watermark_) return;
  caller_watermark_ = t;
  if (t - notified_watermark_ < std::chrono::seconds(1)) return;
  notified_watermark_ = t;
  FlushOffers();  // the samples up to the watermark are the thread's before it may pass them
  {
    std::lock_guard<std::mutex> lock(mu_);
    watermark_ = t;
    has_watermark_ = true;
  }
  cv_.notify_one();
}

void TruthTableBuilder::Command(const VehicleCommand& c, bool late) {
  if (late) {
    // the run's samples from the command's time on were taken before it: not the commands' truth
    std::erase_if(offer_buffer_, [&](const TruthSample& x) { return x.t >= c.t; });
    drop_offered_from_ = std::min(drop_offered_from_.value_or(c.t), c.t);
    const std::lock_guard<std::mutex> lock(mu_);
    if (started_ && position_ >= c.t) ++stale_samples_;
  }
  command_buffer_.push_back(c);
}

void TruthTableBuilder::Offer(const TruthSample& sample) {
  offer_buffer_.push_back(sample);
  if (offer_buffer_.size() >= kOfferBatch) FlushOffers();
}

void TruthTableBuilder::FlushOffers() {
  if (offer_buffer_.empty() && command_buffer_.empty() && !drop_offered_from_) return;
  {
    const std::lock_guard<std::mutex> lock(mu_);
    if (drop_offered_from_) {
      std::erase_if(offered_, [&](const TruthSample& x) { return x.t >= *drop_offered_from_; });
      drop_offered_from_.reset();
    }
    for (const TruthSample& sample : offer_buffer_) {
      while (!offered_.empty() && sample.t - offered_.front().t > kOfferedKeep)
        offered_.pop_front();
      offered_.push_back(sample);
    }
    commands_.insert(commands_.end(), command_buffer_.begin(), command_buffer_.end());
  }
  offer_buffer_.clear();
  command_buffer_.clear();
}

const TruthSample* TruthTableBuilder::FindOffered(Time t) const {
  const auto it = std::lower_bound(offered_.begin(), offered_.end(), t,
                                   [](const TruthSample& s, Time x) { return s.t < x; });
  return it != offered_.end() && it->t == t ? &*it : nullptr;
}

bool TruthTableBuilder::TakeBatch(std::vector<Time>& batch,
                                  std::vector<std::optional<TruthSample>>& offered,
                                  std::vector<VehicleCommand>& commands) {
  batch.clear();
  offered.clear();
  commands.clear();
  std::unique_lock<std::mutex> lock(mu_);
  cv_.wait(lock, [&] {
    return finishing_ || !commands_.empty() ||
           (has_watermark_ && !asked_.empty() && asked_.top() <= watermark_);
  });
  commands.swap(commands_);
  // take what the watermark allows (everything when finishing), in time order
  while (!asked_.empty() && (finishing_ || asked_.top() <= watermark_)) {
    batch.push_back(asked_.top());
    asked_.pop();
  }
  if (!batch.empty()) {
    started_ = true;
    position_ = batch.back();
  }
  if (batch.empty() && commands.empty() && finishing_) return false;
  for (const Time t : batch) {
    const TruthSample* o = FindOffered(t);
    offered.push_back(o ? std::optional<TruthSample>(*o) : std::nullopt);
  }
  // the thread has passed these: no time before the batch's last will be asked of it again
  while (!offered_.empty() && offered_.front().t < position_) offered_.pop_front();
  return true;
}

TruthSample TruthTableBuilder::Integrate(Time t) {
  if (!truth_) truth_.emplace(config_);
  ++integrated_;
  return truth_->Sample(t);
}

void TruthTableBuilder::Work() {
  std::vector<Time> batch;
  std::vector<std::optional<TruthSample>> offered;
  std::vector<VehicleCommand> commands;
  std::vector<Time> batch_times;
  std::vector<TruthSample> batch_samples;
  while (TakeBatch(batch, offered, commands)) {
    // closed loop: the commands up to the watermark are all here before any time it allows
    if (!commands.empty() && !truth_) truth_.emplace(config_);
    for (const VehicleCommand& c : commands)
      truth_->SetCommand(c.t, c.speed_mps, c.steer_or_yaw_rate);
    batch_times.clear();
    batch_samples.clear();
    for (std::size_t i = 0; i < batch.size(); ++i) {
      const Time t = batch[i];
      if (last_done_ && *last_done_ == t) continue;
      last_done_ = t;
      batch_times.push_back(t);
      if (offered[i]) {
        batch_samples.push_back(*offered[i]);
        ++offered_hits_;
      } else {
        batch_samples.push_back(Integrate(t));
      }
    }
    {
      const std::lock_guard<std::mutex> lock(mu_);
      done_times_.insert(done_times_.end(), batch_times.begin(), batch_times.end());
      done_samples_.insert(done_samples_.end(), batch_samples.begin(), batch_samples.end());
    }
    taken_cv_.notify_all();
  }
}

void TruthTableBuilder::WaitTaken(Time t) {
  std::unique_lock<std::mutex> lock(mu_);
  if (!has_watermark_ || t > watermark_) return;  // the thread may not take it yet
  taken_cv_.wait(lock, [&] { return finishing_ || asked_.empty() || asked_.top() > t; });
}

std::size_t TruthTableBuilder::retained() {
  const std::lock_guard<std::mutex> lock(mu_);
  return asked_.size() + late_.size() + offered_.size() + offer_buffer_.size() +
         done_times_.size() + commands_.size() + command_buffer_.size();
}

void TruthTableBuilder::TakeDone(std::vector<Time>& times, std::vector<TruthSample>& samples) {
  times.clear();
  samples.clear();
  const std::lock_guard<std::mutex> lock(mu_);
  times.swap(done_times_);
  samples.swap(done_samples_);
}

TruthTable TruthTableBuilder::Finish() {
  FlushOffers();
  {
    std::lock_guard<std::mutex> lock(mu_);
    finishing_ = true;
  }
  cv_.notify_all();
  if (worker_.joinable()) worker_.join();
  std::vector<Time> times = std::move(done_times_);
  std::vector<TruthSample> samples = std::move(done_samples_);
  // stragglers (asked behind the thread): one more pass for them, merged in time order
  std::erase_if(late_, [&](Time t) { return std::binary_search(times.begin(), times.end(), t); });
  std::sort(late_.begin(), late_.end());
  late_.erase(std::unique(late_.begin(), late_.end()), late_.end());
  if (late_.empty()) return TruthTable(config_, std::move(times), std::move(samples));
  std::vector<TruthSample> extra;
  if (config_.external_commands) {
    // the thread's integrator has every command: it restarts from t = 0 for the earliest
    for (const Time t : late_) extra.push_back(Integrate(t));
  } else {
    const TruthTable table(config_, late_);
    extra = table.samples();
  }
  std::vector<Time> all_t;
  std::vector<TruthSample> all_s;
  std::size_t i = 0, j = 0;
  while (i < times.size() || j < late_.size()) {
    if (j == late_.size() || (i < times.size() && times[i] < late_[j])) {
      all_t.push_back(times[i]);
      all_s.push_back(samples[i++]);
    } else {
      all_t.push_back(late_[j]);
      all_s.push_back(extra[j++]);
    }
  }
  return TruthTable(config_, std::move(all_t), std::move(all_s));
}

}  // namespace hil::harness

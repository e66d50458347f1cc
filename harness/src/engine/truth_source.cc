#include "hil/harness/engine/truth_source.h"

#include <optional>

#include "hil/harness/engine/truth_ahead.h"

namespace hil::harness {
namespace {

// No truth: each event's sample holds only its time.
class EventTimeOnly final : public TruthSource {
 public:
  TruthSample Sample(Time t, const std::vector<std::unique_ptr<Device>>& devices) override {
    (void)devices;
    TruthSample s;
    s.t = t;
    return s;
  }
  bool sample_is_truth() const override { return false; }
};

// The truth integrated on the engine's thread, steered by the commands.
class IntegratedTruth final : public TruthSource {
 public:
  explicit IntegratedTruth(const truth::TruthConfig& config) : integrator_(config) {}
  TruthSample Sample(Time t, const std::vector<std::unique_ptr<Device>>& devices) override {
    (void)devices;
    return integrator_.Sample(t);
  }
  void Command(const VehicleCommand& c) override {
    integrator_.SetCommand(c.t, c.speed_mps, c.steer_or_yaw_rate);
  }
  bool sample_is_truth() const override { return !integrator_.restart_pending(); }
  long late_command_restarts() const override { return integrator_.late_command_restarts(); }

 private:
  truth::TruthIntegrator integrator_;
};

// Open loop: the truth sampled ahead (truth_ahead.h), told each device's next event and the
// event it served last, the schedule it predicts from.
class TruthSampledAhead final : public TruthSource {
 public:
  TruthSampledAhead(const truth::TruthConfig& config, std::size_t devices)
      : ahead_(config), schedule_(devices), last_event_(devices) {}
  TruthSample Sample(Time t, const std::vector<std::unique_ptr<Device>>& devices) override {
    for (std::size_t d = 0; d < devices.size(); ++d) {
      const Time next = devices[d]->next_event_time();
      const Duration period = last_event_[d] ? next - *last_event_[d] : Duration{};
      schedule_[d] = {next, period > Duration{0} ? period : Duration{}};
    }
    ahead_.Plan(schedule_);
    return ahead_.Sample(t);
  }
  void Served(std::size_t d, Time t) override { last_event_[d] = t; }

 private:
  TruthAhead ahead_;
  std::vector<TruthAhead::DeviceSchedule> schedule_;
  std::vector<std::optional<Time>> last_event_;
};

}  // namespace

std::unique_ptr<TruthSource> MakeTruthSource(const truth::TruthConfig* truth, Stepping stepping,
                                             std::size_t devices) {
  if (!truth) return std::make_unique<EventTimeOnly>();
  // open loop in virtual time or lockstep; free-running real time integrates on this thread
  if (stepping != Stepping::kFreeRunning && !truth->external_commands)
    return std::make_unique<TruthSampledAhead>(*truth, devices);
  return std::make_unique<IntegratedTruth>(*truth);
}

}  // namespace hil::harness

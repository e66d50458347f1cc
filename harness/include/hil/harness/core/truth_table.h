#pragma once
/// @file
/// The truth at a set of times, from one pass of the truth integrator. The evaluation needs the
/// truth at every estimate, at every raw fix and on the 10 Hz grid of truth.csv; integrating a
/// long scenario once instead of once per use saves most of the evaluation's time. A sample from
/// the table is the one a fresh TruthIntegrator gives at that time, bit for bit: the integrator's
/// steps do not depend on which times are sampled (truth_integrator.h).

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <queue>
#include <thread>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/truth_sample.h"
#include "hil/truth/local_frame.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

class TruthTable {
 public:
  /// Samples the truth at `times` (any order, repeats allowed; negative times are left out).
  /// Closed loop: `commands` are the actuators' commands of the run, replayed.
  TruthTable(const truth::TruthConfig& config, std::vector<Time> times,
             const std::vector<VehicleCommand>& commands = {});
  /// A table of samples already taken (`times` sorted and unique, one sample each).
  TruthTable(const truth::TruthConfig& config, std::vector<Time> times,
             std::vector<TruthSample> samples);
  /// The sample at `t`, one of the times given. @throws std::out_of_range otherwise.
  const TruthSample& At(Time t) const;
  bool Has(Time t) const;
  /// The times held, sorted, and the sample of each (samples()[i] is the sample at times()[i]).
  const std::vector<Time>& times() const { return times_; }
  const std::vector<TruthSample>& samples() const { return samples_; }
  /// The scenario's local frame (ENU at the origin).
  const truth::LocalFrame& frame() const { return frame_; }

 private:
  std::vector<Time> times_;  // sorted, unique
  std::vector<TruthSample> samples_;
  truth::LocalFrame frame_;
};

/// Builds a TruthTable during the run, on a thread of its own: the times asked for (estimates
/// and fixes as they come, the truth.csv grid) are sampled in time order as far as
/// `Advance(watermark)` allows, so the evaluation after the run finds most of the truth ready
/// instead of integrating the whole scenario again. Times asked for behind what the thread has
/// already passed are sampled by Finish() in a second pass.
///
/// The run's own samples (the engine's, at every device event) can be offered (Offer): a time
/// asked for that one of them has is copied from it, and the thread integrates the truth itself
/// only for the others (from t = 0 at the first of them). The samples are the same either way
/// (the integrator's steps do not depend on the times sampled), but a run whose estimates and
/// fixes fall on device event times (navd's solutions at IMU samples, the 10 Hz grid) then
/// integrates its truth once instead of twice.
class TruthTableBuilder {
 public:
  explicit TruthTableBuilder(const truth::TruthConfig& config);
  ~TruthTableBuilder();
  TruthTableBuilder(const TruthTableBuilder&) = delete;
  TruthTableBuilder& operator=(const TruthTableBuilder&) = delete;

  /// Asks for the truth at `times` (negative times are left out).
  void Ask(const std::vector<Time>& times);
  /// No time before `t` will be asked for any more (except stragglers, see the class comment).
  void Advance(Time t);
  /// Closed loop: a command the actuators gave the run's truth (in the run's order), before the
  /// watermark passes its time. The thread's own integrator obeys them, so that it samples the
  /// times no offered sample has as the run went, and keeps none of them in memory
  /// (truth::CommandSchedule). `late`: the run's truth had passed the command's instant and
  /// re-integrates (TruthIntegrator::late_command_restarts grew): its samples offered from the
  /// command's time on are dropped, and one the thread has taken already counts in stale_samples().
  void Command(const VehicleCommand& c, bool late = false);
  /// A sample the run took (times not decreasing from one call to the next), kept for
  /// kOfferedKeep of emulated time or until the thread has passed it. In closed loop the run's
  /// samples are those of a truth replaying the commands, bit for bit, except after a late command
  /// (Command's `late`).
  void Offer(const TruthSample& sample);
  /// Closed loop: times the thread had taken (scored) before a late command for an instant before
  /// them came: their truth may not be the commands' (0 unless a command came more than the
  /// scoring's horizon late).
  std::size_t stale_samples() const { return stale_samples_; }
  /// Moves the samples taken so far (in time order, each time once) into `times` and `samples`
  /// (cleared first), so that the run's evaluation consumes them as they come and the builder
  /// keeps none. Finish's table then holds only what was not taken (and the stragglers).
  void TakeDone(std::vector<Time>& times, std::vector<TruthSample>& samples);
  /// Waits until the thread has taken every time asked up to `t` (at most the last watermark):
  /// back-pressure, so that a thread behind the run (a loaded machine) cannot pile up the times
  /// asked and the samples offered without bound.
  void WaitTaken(Time t);
  /// Samples everything asked for (and not taken) and returns the table.
  TruthTable Finish();
  /// Times sampled so far from offered samples and by the thread's own integrator (the
  /// stragglers of Finish's second pass not counted).
  std::size_t offered_hits() const { return offered_hits_; }
  /// Times and samples the builder holds now (asked, offered, sampled and not taken).
  std::size_t retained();
  std::size_t integrated() const { return integrated_; }
  /// How long an offered sample is kept for a time the thread has not reached yet: longer than
  /// the run lets the thread lag when the estimator keeps up (RunScoring::kLateHorizon, 60 s, plus
  /// the watermark's 1 s steps), so that the thread copies the run's samples instead of
  /// integrating the truth again (it does when it lags more: the same samples, more time).
  static constexpr Duration kOfferedKeep = std::chrono::seconds(75);

 private:
  void Work();
  /// Waits for times the watermark allows (or the end) and takes them with their offered samples
  /// and the commands handed over; false when finished.
  bool TakeBatch(std::vector<Time>& batch, std::vector<std::optional<TruthSample>>& offered,
                 std::vector<VehicleCommand>& commands);
  /// The thread's integrator sample at `t` (made at the first need; closed loop: from t = 0, with
  /// every command so far).
  TruthSample Integrate(Time t);
  /// The offered sample at `t`, if kept (mu_ held).
  const TruthSample* FindOffered(Time t) const;
  /// Hands the samples offered and the commands given since the last call to the thread (one lock
  /// for many: a lock per device event contended with the thread's, and each wait cost the run a
  /// CPU on a busy machine).
  void FlushOffers();
  static constexpr std::size_t kOfferBatch = 256;

  const truth::TruthConfig& config_;
  std::mutex mu_;
  std::condition_variable cv_;
  std::condition_variable taken_cv_;  // the thread took a batch
  std::priority_queue<Time, std::vector<Time>, std::greater<>>
      asked_;                                   // not yet taken by the thread
  std::vector<Time> late_;                      // asked behind the thread's position
  std::vector<VehicleCommand> commands_;        // handed over, not yet given to truth_ (mu_)
  std::vector<VehicleCommand> command_buffer_;  // the caller's: not yet handed over
  std::optional<Time> drop_offered_from_;  // the caller's: a late command's, at the next hand-over
  std::size_t stale_samples_ = 0;          // the caller's
  std::optional<truth::TruthIntegrator> truth_;  // the thread's until joined
  Time watermark_{};
  bool has_watermark_ = false;
  // the caller's: the thread is woken (and the watermark passed on) for every second of
  // watermark, not every event
  Time notified_watermark_{};
  std::optional<Time> caller_watermark_;
  std::vector<TruthSample> offer_buffer_;  // the caller's: offered, not yet handed over
  bool finishing_ = false;
  Time position_{};  // the latest time the thread has sampled (or taken)
  bool started_ = false;
  std::deque<TruthSample> offered_;  // the run's samples, in time order
  std::vector<Time> done_times_;     // mu_ (the thread appends a batch at a time)
  std::vector<TruthSample> done_samples_;
  std::optional<Time> last_done_;                  // the thread's: the latest time it sampled
  std::size_t offered_hits_ = 0, integrated_ = 0;  // thread-owned until joined
  std::thread worker_;
};

}  // namespace hil::harness

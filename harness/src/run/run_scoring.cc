#include "hil/harness/run/run_scoring.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "hil/harness/report/report.h"
#include "hil/harness/report/run_outputs.h"
#include "hil/harness/scenario/path_file_reader.h"

namespace hil::harness {
namespace {

constexpr Duration kSecond = std::chrono::seconds(1);
// truth.csv's times are asked this far ahead of the run (the builder's thread is kLateHorizon
// behind it, so none is ever behind the thread)
constexpr Duration kGridAhead = std::chrono::seconds(10);
// the decimated series start with buckets this wide (a short run keeps every sample)
constexpr double kFirstBucketS = 0.01;

PlannedPath PathOf(const Scenario& s) {
  return s.closed_loop.enabled ? PlannedPath(ReadPathVertices(s.closed_loop.path_file))
                               : PlannedPathOf(s.truth, s.duration_s);
}

// The vehicle's reference point at `t` for the tracking figures.
TrackSample TrackSampleOf(Time t, const TruthSample& s) {
  const Eigen::Vector3d x = s.q_NB * Eigen::Vector3d::UnitX();
  return {t, s.p_NB_N_m.head<2>(), std::atan2(x.y(), x.x()), s.speed_mps};
}

}  // namespace

RunScoring::Side::Side(std::size_t exact_limit)
    : accuracy(exact_limit), plot(kPlotBuckets, kFirstBucketS) {}

RunScoring::RunScoring(ScoringSetup setup, TruthTableBuilder& truth)
    : setup_(std::move(setup)),
      truth_(truth),
      frame_(setup_.scenario->truth.origin),
      path_(PathOf(*setup_.scenario)),
      est_(setup_.exact_limit),
      fix_(setup_.exact_limit),
      outages_(setup_.scenario->faults, setup_.scenario->reconverged_error_m),
      recovery_(setup_.faults, setup_.scenario->reconverged_error_m),
      timing_(setup_.speed, setup_.exact_limit),
      latency_ms_(setup_.exact_limit),
      truth_plot_(kPlotBuckets, kFirstBucketS),
      ticks_plot_(kPlotBuckets, kFirstBucketS),
      grid_end_(TimeFromSeconds(setup_.scenario->duration_s)) {
  const auto open = [this](Csv& csv, const char* name,
                           const std::function<void(std::string&)>& header) {
    try {
      csv.file.emplace(setup_.dir + "/" + name);
    } catch (...) {
      csv.error = std::current_exception();
      return;
    }
    Write(csv, header);
  };
  open(truth_csv_, "truth.csv", AppendTruthCsvHeader);
  open(est_.csv, "estimate.csv", AppendErrorsCsvHeader);
  open(fix_.csv, "gnss_fixes_errors.csv", AppendErrorsCsvHeader);
}

void RunScoring::Write(Csv& csv, const std::function<void(std::string&)>& append) {
  if (!csv.file) return;
  try {
    append(csv.file->text());
    csv.file->Pass();
  } catch (...) {
    csv.error = std::current_exception();
    csv.file.reset();  // its temporary file goes; the run folder lacks the file
  }
}

void RunScoring::Commit(Csv& csv) {
  if (csv.error) std::rethrow_exception(csv.error);
  if (!csv.file) return;
  csv.file->Commit();
  csv.file.reset();
}

void RunScoring::AddEstimates(const std::vector<EstimateRecord>& records, Time t_now) {
  ask_.clear();
  const Time first = Time{} - kSecond, last = setup_.t_end + kSecond;
  for (const EstimateRecord& r : records) {
    const std::uint64_t arrival = solutions_++;
    if (setup_.wall_time_of) {
      latency_ms_.Add(static_cast<double>((r.wall_rx - setup_.wall_time_of(r.t_validity)).count()) *
                      1e-6 * setup_.speed);
    }
    if (r.t_validity < first || r.t_validity > last) {
      if (outside_++ == 0) {
        first_outside_s_ = ToSeconds(r.t_validity);
        first_outside_arrival_ = arrival;
      }
      continue;
    }
    if (!latest_ || r.t_validity > *latest_) latest_ = r.t_validity;
    // it may still turn out dated after the end, should the run stop early (Finish)
    if (r.t_validity > t_now + kSecond && r.t_validity <= t_now + kLateHorizon)
      ahead_.emplace(r.t_validity, arrival);
    Ask(est_, r, arrival, t_now, ask_);
  }
  if (!ask_.empty()) truth_.Ask(ask_);
}

void RunScoring::AddFixes(const std::vector<EstimateRecord>& fixes) {
  ask_.clear();
  for (const EstimateRecord& r : fixes) Ask(fix_, r, 0, r.t_validity, ask_);
  if (!ask_.empty()) truth_.Ask(ask_);
}

void RunScoring::Ask(Side& side, const EstimateRecord& r, std::uint64_t arrival, Time t_now,
                     std::vector<Time>& ask) {
  const Time t = r.t_validity;
  if (t < setup_.t_from || t > setup_.t_end || t < Time{}) return;  // not scored
  const bool estimate = &side == &est_;
  if (cut_ && t < *cut_) {  // the truth builder has passed it
    if (estimate) ++late_;
    return;
  }
  if (t > t_now + kLateHorizon) {
    if (estimate) ++early_;
    return;
  }
  if (last_sample_ && t == last_sample_->first) {  // sampled already: scored now, in order
    Score(side, estimate, r, last_sample_->second);
    return;
  }
  side.pending.emplace(t, Pending{r, arrival});
  ask.push_back(t);
}

void RunScoring::AskGrid(Time until) {
  ask_.clear();
  for (; next_grid_ask_ <= grid_end_ && next_grid_ask_ <= until; next_grid_ask_ += kTruthCsvStep)
    ask_.push_back(next_grid_ask_);
  if (!ask_.empty()) truth_.Ask(ask_);
}

void RunScoring::Advance(Time t_now) {
  if (next_grid_ask_ <= t_now + kSecond) AskGrid(t_now + kGridAhead);
  while (!ahead_.empty() && ahead_.begin()->first <= t_now + kSecond) ahead_.erase(ahead_.begin());
  // kLateHorizon behind the solutions (the run's time if earlier), at most kMaxLag behind the run
  const std::optional<Time> lead =
      latest_ ? std::min(*latest_, t_now)
              : (setup_.expect_solutions ? std::nullopt : std::optional<Time>(t_now));
  const Time cut = std::max(lead ? *lead - kLateHorizon : t_now - kMaxLag, t_now - kMaxLag);
  if (cut_ && cut <= *cut_) return;
  cut_ = cut;
  truth_.Advance(cut);
  if (last_taken_ && cut - *last_taken_ < kSecond) return;
  last_taken_ = cut;
  // the thread may lag one more horizon (a loaded machine), not more
  truth_.WaitTaken(cut - kLateHorizon);
  truth_.TakeDone(done_t_, done_s_);
  Consume(done_t_, done_s_, setup_.t_end);
}

void RunScoring::Consume(const std::vector<Time>& times, const std::vector<TruthSample>& samples,
                         Time t_to) {
  for (std::size_t i = 0; i < times.size(); ++i) {
    const Time t = times[i];
    const TruthSample& s = samples[i];
    ScoreUpTo(est_, true, t, &s, t_to);
    ScoreUpTo(fix_, false, t, &s, t_to);
    while (next_grid_row_ < t && next_grid_row_ <= grid_end_) next_grid_row_ += kTruthCsvStep;
    if (t == next_grid_row_ && t <= grid_end_) {
      Write(truth_csv_, [&](std::string& text) { AppendTruthCsvRow(text, t, s); });
      truth_plot_.Add(ToSeconds(t), s.p_NB_N_m.x(),
                      Eigen::Vector3d(ToSeconds(t), s.p_NB_N_m.x(), s.p_NB_N_m.y()));
      if (setup_.scenario->closed_loop.enabled) track_.Add(TrackSampleOf(t, s));
      next_grid_row_ += kTruthCsvStep;
    }
    last_sample_.emplace(t, s);
  }
}

void RunScoring::ScoreUpTo(Side& side, bool estimates, Time t, const TruthSample* sample,
                           Time t_to) {
  while (!side.pending.empty() && side.pending.begin()->first <= t) {
    const auto it = side.pending.begin();
    if (it->first == t && sample) {
      if (t <= t_to) Score(side, estimates, it->second.record, *sample);
    } else if (estimates && it->first <= t_to) {
      ++late_;  // its truth never came (counted with the late ones rather than lost silently)
    }
    side.pending.erase(it);
  }
}

void RunScoring::Score(Side& side, bool estimates, const EstimateRecord& r,
                       const TruthSample& sample) {
  ErrorSample e = ErrorOf(r, sample, frame_, estimates ? setup_.p_est_B_m : setup_.p_fix_B_m);
  e.xte_m = path_.CrossTrack(e.est_enu_m.head<2>()) - path_.CrossTrack(e.truth_enu_m.head<2>());
  side.accuracy.Add(e);
  if (estimates) {
    outages_.Add(e);
    recovery_.Add(e);
    timing_.Add(r.t_validity, r.wall_rx);
  }
  Write(side.csv, [&](std::string& text) { AppendErrorsCsvRow(text, e); });
  side.plot.Add(ToSeconds(e.t), e.horizontal(), e);
}

TruthTable RunScoring::Finish(Time t_end) {
  // the rest of truth.csv's grid (to the scenario's end, though the run stopped early) a
  // horizon at a time, as the run would have had it
  while (next_grid_ask_ <= grid_end_) {
    const Time until = next_grid_ask_ + kLateHorizon;
    AskGrid(until);
    truth_.Advance(until);
    truth_.WaitTaken(until);
    truth_.TakeDone(done_t_, done_s_);
    Consume(done_t_, done_s_, t_end);
  }
  AskGrid(grid_end_);
  TruthTable table = truth_.Finish();
  Consume(table.times(), table.samples(), t_end);
  ScoreUpTo(est_, true, Time::max(), nullptr, t_end);
  ScoreUpTo(fix_, false, Time::max(), nullptr, t_end);
  // a run that stopped early: what was dated after its stop is dated outside it
  for (const auto& [t, arrival] : ahead_) {
    if (t <= t_end + kSecond) continue;
    if (outside_++ == 0 || arrival < first_outside_arrival_) {
      first_outside_s_ = ToSeconds(t);
      first_outside_arrival_ = arrival;
    }
  }
  ahead_.clear();
  return table;
}

void RunScoring::AddControlTick(Time t, double commanded_yaw_rate_dps, double yaw_rate_dps) {
  ticks_plot_.Add(ToSeconds(t), yaw_rate_dps,
                  Eigen::Vector3d(ToSeconds(t), commanded_yaw_rate_dps, yaw_rate_dps));
}

void RunScoring::AddSteeringTick(Time t, double commanded_steer_deg, double steer_deg) {
  steering_ticks_ = true;
  ticks_plot_.Add(ToSeconds(t), steer_deg,
                  Eigen::Vector3d(ToSeconds(t), commanded_steer_deg, steer_deg));
}

ReportSeries RunScoring::TakeSeries() {
  ReportSeries s;
  s.estimate_errors = est_.plot.Points();
  s.fix_errors = fix_.plot.Points();
  for (const Eigen::Vector3d& p : truth_plot_.Points()) {
    s.truth_t_s.push_back(p.x());
    s.truth_en_m.emplace_back(p.y(), p.z());
  }
  for (const Eigen::Vector3d& k : ticks_plot_.Points()) {
    s.tick_t_s.push_back(k.x());
    (steering_ticks_ ? s.commanded_steer_deg : s.commanded_yaw_rate_dps).push_back(k.y());
    (steering_ticks_ ? s.actual_steer_deg : s.actual_yaw_rate_dps).push_back(k.z());
  }
  s.estimate_cdf = CdfPoints(est_.accuracy.horizontal(), ReportSeries::kCdfPoints);
  s.fix_cdf = CdfPoints(fix_.accuracy.horizontal(), ReportSeries::kCdfPoints);
  s.latency_ms = latency_ms_;
  // the open loop's map draws the planned path (closed loop: AddClosedLoopSeries)
  if (!setup_.scenario->closed_loop.enabled) s.path_en_m = path_.vertices();
  return s;
}

std::size_t RunScoring::retained() const {
  return est_.pending.size() + fix_.pending.size() + est_.accuracy.retained() +
         fix_.accuracy.retained() + est_.plot.retained() + fix_.plot.retained() +
         truth_plot_.retained() + ticks_plot_.retained() + timing_.retained() +
         latency_ms_.retained() + ahead_.size() + done_t_.size() + truth_.retained() +
         track_.in_memory();
}

}  // namespace hil::harness

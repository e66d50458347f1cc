#pragma once
/// @file
/// The run's evaluation as the run goes, in memory bounded whatever the run's length (issue 40:
/// 13.7 MB per emulated hour when every solution, fix, truth sample and error was kept for an
/// evaluation at the end). The solutions and raw fixes are handed over as they come; each waits
/// only until the truth builder (core/truth_table.h) has sampled its time, is scored then and
/// dropped: running sums and QuantileSketch for the accuracy (AccuracyAccumulator), each outage
/// window's figures as its solutions come (OutageAccumulator), the fault recovery times
/// (RecoveryTimeAccumulator), the output timing (OutputTimingAccumulator); estimate.csv,
/// gnss_fixes_errors.csv and truth.csv are written as their lines come; the plots get decimated
/// series (SeriesDecimator) and the CDF's points (CdfPoints).
///
/// The horizon (kLateHorizon, our choice): the truth builder's thread follows the latest time of
/// validity of the solutions so far (or the run's time, if earlier) kLateHorizon behind, so a
/// solution may come up to that long after a later-dated one and still be scored, in time order
/// with the others (the metrics are the same bits as an evaluation of the whole set at the end).
/// Following the solutions, not the run's time, keeps the verdict independent of the wall clock:
/// in virtual mode the run may be far ahead of what hil has read of the estimator's output on a
/// loaded machine. The thread is never more than kMaxLag behind the run's time, so memory stays
/// bounded with an estimator that says nothing (or nothing new). A solution dated before what the
/// thread has passed, or more than kLateHorizon after the run's time when it arrives, is not
/// scored: a problem of the report. Closed loop: the same, the builder's integrator obeying the
/// run's commands (TruthTableBuilder::Command); the truth's track on truth.csv's grid (10 Hz,
/// 40 B a sample) is kept on disk for the tracking figures (track(), spilled_track.h).

#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/harness/core/truth_table.h"
#include "hil/harness/eval/cross_track.h"
#include "hil/harness/eval/evaluator.h"
#include "hil/harness/eval/outage_metrics.h"
#include "hil/harness/eval/path_tracking.h"
#include "hil/harness/eval/series_decimator.h"
#include "hil/harness/eval/spilled_track.h"
#include "hil/harness/faults/fault_report.h"
#include "hil/harness/report/output_file.h"
#include "hil/harness/report/report_html.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

/// What RunScoring needs of the run.
struct ScoringSetup {
  const Scenario* scenario = nullptr;
  std::string dir;         ///< the run folder (estimate.csv, gnss_fixes_errors.csv, truth.csv)
  Time t_from{}, t_end{};  ///< the evaluated window (t_end: the scenario's end)
  Eigen::Vector3d p_est_B_m = Eigen::Vector3d::Zero();  ///< the point the solutions describe
  Eigen::Vector3d p_fix_B_m = Eigen::Vector3d::Zero();  ///< the antenna (raw fixes)
  std::vector<FaultInjection> faults;                   ///< the timeline's records (recovery times)
  double speed = 1.0;  ///< wall intervals → emulated (arrival jitter)
  /// Real time: the wall-clock instant of an emulated time (latency); empty in virtual mode.
  std::function<WallTime(Time)> wall_time_of;
  bool expect_solutions = true;  ///< false: no estimator (the thread follows the run's time)
  std::size_t exact_limit = QuantileSketch::kExactLimit;  ///< values each percentile holds
};

class RunScoring {
 public:
  static constexpr Duration kLateHorizon = std::chrono::seconds(60);
  /// Our choice: 10 min of emulated time (2 s of wall time at 300x).
  static constexpr Duration kMaxLag = std::chrono::seconds(600);
  /// Time buckets of each plotted series (SeriesDecimator): at most 3 points per bucket.
  static constexpr std::size_t kPlotBuckets = 2048;

  /// Asks `truth` for truth.csv's times as the run goes. @throws OutputWriteError when a file of
  /// the run folder cannot be made.
  RunScoring(ScoringSetup setup, TruthTableBuilder& truth);

  /// The solutions and raw fixes that came since the last call; `t_now`: the run's time.
  void AddEstimates(const std::vector<EstimateRecord>& records, Time t_now);
  void AddFixes(const std::vector<EstimateRecord>& fixes);
  /// Lets the truth builder follow the run to kLateHorizon behind `t_now` and scores what it has
  /// sampled.
  void Advance(Time t_now);
  /// The end of the run (`t_end`: the scenario's end, or the time the run stopped): the rest is
  /// sampled and scored. Returns the truth table of what was sampled at the end (stragglers).
  TruthTable Finish(Time t_end);

  // what Finish leaves
  AccuracyMetrics metrics() const { return est_.accuracy.Metrics(); }
  AccuracyMetrics baselines() const { return fix_.accuracy.Metrics(); }
  OutputTiming timing(Time t_from, Time t_end) const { return timing_.Result(t_from, t_end); }
  std::vector<OutageMetrics> outages() const { return outages_.Result(); }
  void ApplyRecoveryTimes(std::vector<FaultInjection>& faults) const { recovery_.Apply(faults); }
  const QuantileSketch& latency_ms() const { return latency_ms_; }
  std::uint64_t solutions() const { return solutions_; }
  /// Solutions dated before −1 s or after the end + 1 s; the first of them (arrival order).
  std::uint64_t outside_run() const { return outside_; }
  std::optional<double> first_outside_s() const { return first_outside_s_; }
  /// Solutions not scored for the horizon: arrived too late, or dated too far ahead.
  std::uint64_t too_late() const { return late_; }
  std::uint64_t too_early() const { return early_; }
  /// Closed loop, differential-drive base: a control tick's commanded and actual yaw rates, for
  /// the plots (decimated as the other series).
  void AddControlTick(Time t, double commanded_yaw_rate_dps, double yaw_rate_dps);
  /// A steering ECU's control tick: commanded and actual road-wheel angle (the plots; a run has
  /// a base or a steering ECU, not both).
  void AddSteeringTick(Time t, double commanded_steer_deg, double steer_deg);
  /// Closed loop: the truth's track at truth.csv's times (10 Hz, the whole grid to the
  /// scenario's end), in time order, on disk but for its last samples.
  const SpilledTrack& track() const { return track_; }
  /// The plots' series (moves them out).
  ReportSeries TakeSeries();
  /// Writes out truth.csv, estimate.csv and gnss_fixes_errors.csv. @throws what writing them threw.
  void CommitTruthCsv() { Commit(truth_csv_); }
  void CommitEstimateCsv() { Commit(est_.csv); }
  void CommitFixCsv() { Commit(fix_.csv); }

  /// Records, samples, values and points held now: bounded whatever the run's length.
  std::size_t retained() const;

 private:
  struct Pending {
    EstimateRecord record;
    std::uint64_t arrival = 0;
  };
  struct Csv {
    std::optional<OutputFile> file;
    std::exception_ptr error;
  };
  // one stream of records (the solutions, or the raw fixes)
  struct Side {
    explicit Side(std::size_t exact_limit);
    std::multimap<Time, Pending> pending;
    AccuracyAccumulator accuracy;
    SeriesDecimator<ErrorSample> plot;
    Csv csv;
  };
  void Ask(Side& side, const EstimateRecord& r, std::uint64_t arrival, Time t_now,
           std::vector<Time>& ask);
  void AskGrid(Time until);
  void Consume(const std::vector<Time>& times, const std::vector<TruthSample>& samples, Time t_to);
  void ScoreUpTo(Side& side, bool estimates, Time t, const TruthSample* sample, Time t_to);
  void Score(Side& side, bool estimates, const EstimateRecord& r, const TruthSample& sample);
  void Write(Csv& csv, const std::function<void(std::string&)>& append);
  static void Commit(Csv& csv);

  ScoringSetup setup_;
  TruthTableBuilder& truth_;
  truth::LocalFrame frame_;
  PlannedPath path_;
  Side est_, fix_;
  OutageAccumulator outages_;
  RecoveryTimeAccumulator recovery_;
  OutputTimingAccumulator timing_;
  QuantileSketch latency_ms_;
  Csv truth_csv_;
  SeriesDecimator<Eigen::Vector3d> truth_plot_;  // (t, east, north)
  SpilledTrack track_;                           // closed loop
  SeriesDecimator<Eigen::Vector3d> ticks_plot_;  // (t, commanded, actual yaw rate or steer angle)
  bool steering_ticks_ = false;                  // ticks_plot_ holds road-wheel angles
  Time grid_end_, next_grid_ask_{}, next_grid_row_{};
  std::optional<Time> cut_;         // the builder's watermark so far
  std::optional<Time> latest_;      // the latest time of validity of a solution in the run
  std::optional<Time> last_taken_;  // when the builder's samples were last taken
  std::optional<std::pair<Time, TruthSample>> last_sample_;  // the latest sample consumed
  std::vector<Time> ask_, done_t_;
  std::vector<TruthSample> done_s_;
  std::multimap<Time, std::uint64_t> ahead_;  // dated > 1 s after the run's time (arrival)
  std::uint64_t solutions_ = 0, outside_ = 0, late_ = 0, early_ = 0;
  std::optional<double> first_outside_s_;
  std::uint64_t first_outside_arrival_ = 0;
};

}  // namespace hil::harness

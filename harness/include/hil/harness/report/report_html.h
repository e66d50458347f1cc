#pragma once
/// @file
/// The human-readable run report: RUN_DIR/report.html with its plots as SVG images in
/// RUN_DIR/plots/ — trajectory (truth, estimate, raw GNSS), horizontal error against time with the
/// GNSS outages shaded, the empirical CDF of the horizontal error, and (real-time runs) the latency
/// histogram — followed by the verdict table, the metrics, outages and the run's artefacts.

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "hil/harness/eval/evaluator.h"
#include "hil/harness/eval/quantile_sketch.h"
#include "hil/harness/report/report.h"

namespace hil::harness {

/// The time series the plots need, bounded whatever the run's length (a run fills them as it goes:
/// RunScoring, harness/run/run_scoring.h).
struct ReportSeries {
  /// The errors for the trajectory and error-against-time plots, decimated in time
  /// (SeriesDecimator: per time bucket the first sample and those of the smallest and largest
  /// horizontal error; every sample of a short run).
  std::vector<ErrorSample> estimate_errors;
  std::vector<ErrorSample> fix_errors;
  /// The truth's track at truth.csv's times, decimated the same way (key: east).
  std::vector<double> truth_t_s;
  std::vector<Eigen::Vector2d> truth_en_m;
  /// The empirical CDF of the horizontal error of every sample: (error m, % at or below), at most
  /// about kCdfPoints points (CdfPoints).
  std::vector<std::pair<double, double>> estimate_cdf, fix_cdf;
  static constexpr std::size_t kCdfPoints = 2000;
  QuantileSketch latency_ms;  ///< every solution's latency; empty outside real-time mode
  /// Closed loop: the planned path, and per control tick the commanded and actual yaw rate.
  std::vector<Eigen::Vector2d> path_en_m;
  std::vector<double> tick_t_s, commanded_yaw_rate_dps, actual_yaw_rate_dps;
};

/// Closed loop: path + truth + estimate, XTE against distance, commanded against actual steering
/// (report_closed_loop_plots.cc). Appends the files written to `files`.
void WriteClosedLoopPlots(const RunReport& report, const ReportSeries& series,
                          const std::string& run_dir, std::vector<std::string>& files);

/// The plot files written, relative to the run folder.
std::vector<std::string> WritePlots(const RunReport& report, const ReportSeries& series,
                                    const std::string& run_dir);

/// Writes RUN_DIR/report.html (and the plots). @throws std::runtime_error naming the file.
void WriteReportHtml(const RunReport& report, const ReportSeries& series,
                     const std::string& run_dir);

}  // namespace hil::harness

#pragma once
/// @file
/// The human-readable run report: RUN_DIR/report.html with its plots as SVG images in
/// RUN_DIR/plots/ — trajectory (truth, estimate, raw GNSS), horizontal error against time with the
/// GNSS outages shaded, the empirical CDF of the horizontal error, and (real-time runs) the latency
/// histogram — followed by the verdict table, the metrics, outages and the run's artefacts.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/harness/eval/evaluator.h"
#include "hil/harness/report/report.h"

namespace hil::harness {

/// The time series the plots need.
struct ReportSeries {
  std::vector<ErrorSample> estimate_errors;
  std::vector<ErrorSample> fix_errors;
  std::vector<double> truth_t_s;
  std::vector<Eigen::Vector2d> truth_en_m;
  std::vector<double> latency_ms;  ///< empty outside real-time mode
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

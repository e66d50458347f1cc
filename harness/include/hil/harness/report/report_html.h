#pragma once
/// @file
/// The human-readable run report, a sign-off document: RUN_DIR/report.html, one self-contained
/// file (its charts are inline SVG, nothing is fetched when it is viewed; it prints to PDF from a
/// browser). It says what was tested (run_header.h), the verdict with each criterion's meaning,
/// the values outside their band, the map with a zoom on the worst segment, the cross-track error
/// over distance, the error against time with GNSS outages shaded, the NEES with its χ² bands,
/// the accuracy against the raw fixes, the faults with their effects, what the harness measured
/// of itself, and a signature block. Each chart is also written to RUN_DIR/plots/*.svg.

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "hil/harness/core/quantile_sketch.h"
#include "hil/harness/eval/evaluator.h"
#include "hil/harness/report/report.h"
#include "hil/harness/report/run_header.h"
#include "hil/harness/report/svg_plot.h"

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
  /// Closed loop: the planned path, and per control tick the commanded and actual yaw rate (a
  /// differential-drive base) or road-wheel angle (a steering ECU on ISO 11783-7), left positive.
  std::vector<Eigen::Vector2d> path_en_m;
  std::vector<double> tick_t_s, commanded_yaw_rate_dps, actual_yaw_rate_dps;
  std::vector<double> commanded_steer_deg, actual_steer_deg;
};

/// Closed loop: path + truth + estimate, XTE against distance, commanded against actual steering
/// (report_closed_loop_plots.cc). Appends the files written to `files`.
void WriteClosedLoopPlots(const RunReport& report, const ReportSeries& series,
                          const std::string& run_dir, std::vector<std::string>& files);

/// Closed loop: commanded against actual steering at each control tick: the base's yaw rate, or
/// else the steering ECU's road-wheel angle; nullopt when the run recorded neither (no empty
/// chart in the report).
std::optional<PlotChart> SteeringChart(const ReportSeries& series);

/// The latency histogram; @pre series.latency_ms is not empty (real time or scaled).
PlotChart LatencyChart(const ReportSeries& series);

/// Writes RUN_DIR/report.html (and the plots). @throws std::runtime_error naming the file.
void WriteReportHtml(const RunReport& report, const ReportSeries& series, const RunHeader& header,
                     const std::string& run_dir);

}  // namespace hil::harness

#pragma once
/// @file
/// The charts of the sign-off report (report.html), built from the run's report and its plot
/// series (report_html.h), each a PlotChart that RenderSvg draws: the map (equal axes fitted to
/// the truth, the estimate and the raw fixes; the planned path drawn but not fitted), the zoom on
/// the worst segment, the cross-track error against distance, the horizontal error against time
/// with the GNSS outages shaded, and the NEES against time with its χ² bands.

#include <optional>

#include "hil/harness/report/report.h"
#include "hil/harness/report/report_html.h"
#include "hil/harness/report/svg_plot.h"

namespace hil::harness {

/// The worst-segment zoom shows the square around the largest horizontal error (centred between
/// the truth and the estimate then) of half side kZoomErrors × that error, at least kZoomMinHalfM:
/// ours, so that the error spans a quarter of the zoom's height and a centimetre error of an RTK
/// run is still seen against its neighbouring solutions.
inline constexpr double kZoomErrors = 2.0, kZoomMinHalfM = 0.05;

/// Where the estimate was worst: the sample of the largest horizontal error, and the east/north
/// range of the zoom around it.
struct WorstSegment {
  double t_worst_s = 0, error_m = 0;
  Eigen::Vector2d truth_en_m = Eigen::Vector2d::Zero(), estimate_en_m = Eigen::Vector2d::Zero();
  PlotRange range;
};
/// nullopt when the run has no scored estimate.
std::optional<WorstSegment> FindWorstSegment(const ReportSeries& series);

/// The χ² bands of the NEES chart, for a consistent estimator (2 DOF horizontal NEES): 99 % of
/// single samples lie in [chi2_0.005(2), chi2_0.995(2)]; a mean over 10 independent samples in
/// [chi2_0.005(20) / 10, chi2_0.995(20) / 10] (the default criterion nees_horizontal's bound).
inline constexpr double kNeesSampleLow = 0.01003, kNeesSampleHigh = 10.597;
inline constexpr double kNeesMeanLow = 0.7434, kNeesMeanHigh = 4.0;
/// The NEES chart's moving mean spans this many seconds (about ten independent errors of a
/// NEO-5M, whose errors stay correlated for seconds; default_criteria.h).
inline constexpr double kNeesMeanWindowS = 10.0;

/// Distance travelled by the truth (m) at each of `t_s`, from the truth track (linear in time
/// between its samples; 0 before it starts).
std::vector<double> DistanceTravelled(const ReportSeries& series, const std::vector<double>& t_s);

PlotChart MapChart(const RunReport& report, const ReportSeries& series);
/// nullopt without a worst segment.
std::optional<PlotChart> WorstSegmentChart(const ReportSeries& series);
PlotChart CrossTrackChart(const RunReport& report, const ReportSeries& series);
PlotChart ErrorTimeChart(const RunReport& report, const ReportSeries& series);
PlotChart NeesChart(const ReportSeries& series);

}  // namespace hil::harness

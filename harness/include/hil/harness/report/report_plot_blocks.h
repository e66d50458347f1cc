#pragma once
/// @file
/// The pieces every plot of report.html is built from (report_html.cc,
/// report_closed_loop_plots.cc): the shared colours, series through east/north points, and writing
/// one chart into RUN_DIR/plots.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/harness/eval/evaluator.h"
#include "hil/harness/report/svg_plot.h"

namespace hil::harness {

inline constexpr const char* kTruthColor = "#222222";
inline constexpr const char* kEstimateColor = "#1f77b4";
inline constexpr const char* kGnssColor = "#d62728";
inline constexpr const char* kPathColor = "#2ca02c";

/// An empty series with its legend label, colour and style.
PlotSeries NamedSeries(const std::string& label, const char* color,
                       PlotSeries::Style style = PlotSeries::Style::kLine);
/// A series through east/north points (m): the truth, the planned path.
PlotSeries EnSeries(const std::string& label, const char* color,
                    const std::vector<Eigen::Vector2d>& en_m,
                    PlotSeries::Style style = PlotSeries::Style::kLine);
/// A series through the estimated east/north (m) of error samples: the estimate, the raw fixes.
PlotSeries EstimatedEnSeries(const std::string& label, const char* color,
                             const std::vector<ErrorSample>& errors,
                             PlotSeries::Style style = PlotSeries::Style::kLine);
/// Renders `chart` as SVG into dir/file (file relative to the run directory, e.g.
/// "plots/trajectory.svg") and appends `file` to `files`.
void WritePlot(const PlotChart& chart, const std::string& dir, const std::string& file,
               std::vector<std::string>& files);

}  // namespace hil::harness

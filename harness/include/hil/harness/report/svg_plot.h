#pragma once
/// @file
/// Minimal SVG charts for the run report (no plotting dependency): line, point and bar series on
/// linear axes with ticks, shaded x-intervals (e.g. GNSS outages), a legend, and optionally equal
/// scales on both axes (trajectories). The output is a standalone SVG image.

#include <string>
#include <vector>

namespace hil::harness {

struct PlotSeries {
  enum class Style { kLine, kPoints, kBars };
  std::string label;
  std::string color = "#1f77b4";
  Style style = Style::kLine;
  std::vector<double> x, y;  ///< same length; bars: x is the bin centre, width from bar_width
  double bar_width = 0;
};

struct PlotBand {
  double x0 = 0, x1 = 0;
  std::string label;
};

struct PlotChart {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  std::vector<PlotBand> bands;         ///< shaded vertical intervals
  bool equal_aspect = false;           ///< same metres per pixel on both axes
  bool y_from_zero = false;            ///< y axis starts at 0
  std::string empty_note = "no data";  ///< the note an empty chart shows in its frame
  int width_px = 760, height_px = 420;
};

/// Renders the chart as an SVG document. An empty chart renders its frame and its `empty_note`.
std::string RenderSvg(const PlotChart& chart);

/// "Nice" tick positions (1, 2, 5 × 10^k steps) covering [lo, hi].
std::vector<double> NiceTicks(double lo, double hi, int target_count);

/// An SVG coordinate or length: two decimals.
std::string SvgNum(double v);

}  // namespace hil::harness

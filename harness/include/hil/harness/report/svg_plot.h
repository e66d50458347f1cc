#pragma once
/// @file
/// Minimal SVG charts for the run report (no plotting dependency): line, point and bar series on
/// linear axes with ticks, shaded x-intervals (e.g. GNSS outages), a legend, and optionally equal
/// scales on both axes (trajectories), a logarithmic y axis (NEES), shaded y-intervals (a χ²
/// band) and a fixed data range (a zoom). The output is an SVG document that can also stand inline
/// in an HTML page (its clip path's id is the chart's own).

#include <optional>
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
  /// false: drawn but not fitted (clipped to the axes the other series set), e.g. a planned path
  /// that runs on beyond where the vehicle went
  bool fits = true;
  double line_width_px = 1.6;
};

/// A shaded interval: of x (a vertical strip, e.g. a GNSS outage) or of y (a horizontal strip,
/// e.g. a χ² band).
struct PlotBand {
  double x0 = 0, x1 = 0;
  std::string label;
  std::string color = "#f4b183";
};

/// The data range a chart shows.
struct PlotRange {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
};

/// A rectangle in data coordinates drawn as an outline (e.g. where a zoom panel looks).
struct PlotBox {
  PlotRange range;
  std::string label;
};

struct PlotChart {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  std::vector<PlotBand> bands;  ///< shaded vertical intervals (x0, x1); legend "band_legend"
  std::string band_legend = "GNSS outage";
  std::vector<PlotBand> y_bands;       ///< shaded horizontal intervals (x0, x1 are y values)
  std::vector<PlotBox> boxes;          ///< outlined rectangles
  bool equal_aspect = false;           ///< same metres per pixel on both axes
  bool y_from_zero = false;            ///< y axis starts at 0
  bool y_log = false;                  ///< log10 y axis: values <= 0 are not drawn
  std::optional<PlotRange> range;      ///< the data range to show (else fitted to the data)
  std::string empty_note = "no data";  ///< the note an empty chart shows in its frame
  std::string id = "plot";             ///< the clip path's id: unique within an HTML page
  int width_px = 760, height_px = 420;
  int legend_columns = 3;  ///< legend entries per row
};

/// Bounds of FitSizeToData, in pixels of the plot area (inside the axes): ours, so that a map
/// stays readable on a page 1000 px wide and its legend's labels keep apart.
struct PlotSizeLimits {
  double min_plot_height_px = 240, max_plot_height_px = 860, min_plot_width_px = 320;
  /// a plot area narrower than this lays its legend out in two columns, and in one below the next
  double two_columns_below_px = 640, one_column_below_px = 440;
};

/// Sizes an equal-aspect chart (a map) so that its plot area has the aspect of the data it shows
/// (as ChartRange fits it, before widening one axis): the height follows the data at the chart's
/// width, within the limits; data taller than max_plot_height_px narrows the chart instead, down
/// to min_plot_width_px. A map then shows about its data on both axes, not a strip of it inside
/// a fixed frame.
void FitSizeToData(PlotChart& chart, const PlotSizeLimits& limits = {});

/// Renders the chart as an SVG document. An empty chart renders its frame and its `empty_note`.
std::string RenderSvg(const PlotChart& chart);

/// The data range RenderSvg shows: `range` when set, else every finite point of the series that
/// fit and every x band, padded (and widened on one axis for equal scales). With y_log the y
/// values are log10 of the data.
PlotRange ChartRange(const PlotChart& chart);

/// "Nice" tick positions (1, 2, 5 × 10^k steps) covering [lo, hi].
std::vector<double> NiceTicks(double lo, double hi, int target_count);

/// An SVG coordinate or length: two decimals.
std::string SvgNum(double v);

}  // namespace hil::harness

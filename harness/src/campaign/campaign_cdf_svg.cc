// The CDF across seeds of one metric, one step line per group, as a standalone SVG.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "hil/harness/campaign/campaign_report.h"
#include "hil/harness/report/report.h"
#include "hil/harness/report/svg_plot.h"

namespace hil::harness {
namespace {

using nlohmann::json;

constexpr double kW = 640, kH = 320, kLeft = 60, kRight = 20, kTop = 30, kBottom = 40;
constexpr double kLegendGap = 12;  // below the axis label (at kH - 8), above the first legend row
constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

struct Line {
  std::string label;
  std::vector<double> x;  // sorted
};

std::vector<Line> Lines(const json& summary, const std::string& metric) {
  std::vector<Line> lines;
  for (const auto& g : summary.value("groups", json::array())) {
    const std::string id = g.value("id", ""), settings = GroupSettingsText(g);
    Line l{settings.empty() ? id : id + ": " + settings, {}};
    for (const auto& r : summary.value("runs", json::array())) {
      if (r.value("group", "") != id || !r.contains("metric_table")) continue;
      const json v = r["metric_table"].value(metric, json(nullptr));
      if (v.is_number()) l.x.push_back(v.get<double>());
    }
    std::sort(l.x.begin(), l.x.end());
    if (!l.x.empty()) lines.push_back(l);
  }
  return lines;
}

// Groups whose scales differ by ten times or more (ratio of their medians) share a log axis, so
// that no group is squeezed against one edge; every value must then be positive.
constexpr double kLogScaleRatio = 10.0;

bool WantsLogScale(const std::vector<Line>& lines) {
  double lo_median = 0, hi_median = 0;
  for (const auto& l : lines) {
    if (l.x.front() <= 0) return false;
    const double m = l.x[l.x.size() / 2];
    lo_median = lo_median == 0 ? m : std::min(lo_median, m);
    hi_median = std::max(hi_median, m);
  }
  return lines.size() > 1 && hi_median >= kLogScaleRatio * lo_median;
}

// `lo`, `hi`: the axis ends, in log10 of the metric when `log`.
std::string Axes(double lo, double hi, const std::string& metric, double height, bool log) {
  const double plot_h = height - kTop - kBottom;
  std::string s = "<rect x=\"" + SvgNum(kLeft) + "\" y=\"" + SvgNum(kTop) + "\" width=\"" +
                  SvgNum(kW - kLeft - kRight) + "\" height=\"" + SvgNum(plot_h) +
                  "\" fill=\"none\" stroke=\"#333\"/>\n";
  char b[256];
  // x ticks: on a log axis five at equal ratios; on a linear one at round values (1, 2, 5 x 10^k)
  std::vector<double> ticks = log ? std::vector<double>{} : NiceTicks(lo, hi, 5);
  for (int i = 0; log && i <= 4; ++i) ticks.push_back(lo + (hi - lo) * i / 4.0);
  for (const double v : ticks) {
    const double fx = kLeft + (kW - kLeft - kRight) * (v - lo) / (hi - lo);
    std::snprintf(
        b, sizeof b,
        "<text x=\"%.2f\" y=\"%.2f\" font-size=\"11\" text-anchor=\"middle\">%.3g</text>\n", fx,
        kTop + plot_h + 15, log ? std::pow(10.0, v) : (std::abs(v) < 1e-12 ? 0.0 : v));
    s += b;
  }
  for (int i = 0; i <= 4; ++i) {
    const double fy = kTop + plot_h * (1.0 - i / 4.0);
    std::snprintf(b, sizeof b,
                  "<text x=\"%.2f\" y=\"%.2f\" font-size=\"11\" text-anchor=\"end\">%.2f</text>\n",
                  kLeft - 5, fy + 4, i / 4.0);
    s += b;
  }
  s += "<text x=\"" + SvgNum(kW / 2) + "\" y=\"" + SvgNum(kTop + plot_h + 32) +
       "\" font-size=\"12\" text-anchor=\"middle\">" + XmlEscape(metric) +
       (log ? " (log scale: the groups' medians differ 10× or more)" : "") + "</text>\n";
  s += "<text x=\"" + SvgNum(kW / 2) +
       "\" y=\"18\" font-size=\"13\" text-anchor=\"middle\">CDF over "
       "seeds: " +
       XmlEscape(metric) + "</text>\n";
  return s;
}

}  // namespace

std::string CdfSvg(const json& summary, const std::string& metric) {
  const std::vector<Line> lines = Lines(summary, metric);
  if (lines.empty()) return "";
  const bool log = WantsLogScale(lines);
  const auto axis = [log](double v) { return log ? std::log10(v) : v; };
  double lo = axis(lines[0].x.front()), hi = axis(lines[0].x.back());
  for (const auto& l : lines)
    lo = std::min(lo, axis(l.x.front())), hi = std::max(hi, axis(l.x.back()));
  const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(0.5, 0.1 * std::abs(lo));
  lo -= pad, hi += pad;
  const double height = kH + kLegendGap + 14.0 * static_cast<double>(lines.size());
  const double plot_h = kH - kTop - kBottom, plot_w = kW - kLeft - kRight;
  const auto px = [&](double x) { return kLeft + plot_w * (axis(x) - lo) / (hi - lo); };
  const auto py = [&](double f) { return kTop + plot_h * (1.0 - f); };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + SvgNum(kW) +
                  "\" height=\"" + SvgNum(height) + "\" viewBox=\"0 0 " + SvgNum(kW) + " " +
                  SvgNum(height) + "\">\n";
  s += Axes(lo, hi, metric, kH, log);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Line& l = lines[i];
    const char* colour = kColours[i % (sizeof kColours / sizeof kColours[0])];
    const double n = static_cast<double>(l.x.size());
    std::string d = "M" + SvgNum(kLeft) + "," + SvgNum(py(0));
    for (std::size_t k = 0; k < l.x.size(); ++k) {
      d += " H" + SvgNum(px(l.x[k])) + " V" + SvgNum(py(static_cast<double>(k + 1) / n));
    }
    d += " H" + SvgNum(kLeft + plot_w);
    s += std::string("<path fill=\"none\" stroke=\"") + colour + "\" stroke-width=\"1.5\" d=\"" +
         d + "\"/>\n";
    const double ly = kH + kLegendGap + 14.0 * static_cast<double>(i);
    s += std::string("<rect x=\"") + SvgNum(kLeft) + "\" y=\"" + SvgNum(ly - 8) +
         "\" width=\"12\" height=\"3\" fill=\"" + colour + "\"/><text x=\"" + SvgNum(kLeft + 18) +
         "\" y=\"" + SvgNum(ly) + "\" font-size=\"11\">" + XmlEscape(l.label) + " (" +
         std::to_string(l.x.size()) + " runs)</text>\n";
  }
  return s + "</svg>\n";
}

}  // namespace hil::harness

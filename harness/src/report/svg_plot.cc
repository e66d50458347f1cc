#include "hil/harness/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "hil/harness/report/fixed_text.h"
#include "hil/harness/report/report.h"

namespace hil::harness {
std::string SvgNum(double v) {
  std::string s;
  AppendFixed(s, v, 2);
  return s;
}

namespace {

std::string TickLabel(double v, double step) {
  char b[32];
  const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(b, sizeof b, "%.*f", std::clamp(decimals, 0, 6),
                std::abs(v) < step * 1e-6 ? 0.0 : v);
  return b;
}

}  // namespace

std::vector<double> NiceTicks(double lo, double hi, int target_count) {
  std::vector<double> t;
  if (!(hi > lo) || target_count < 1) return t;
  const double raw = (hi - lo) / target_count;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) t.push_back(v);
  return t;
}

namespace {

// The plot area in pixels (margins left and top, width and height) and the data range it shows.
struct PlotFrame {
  double ml, mt, pw, ph;
  double x0, x1, y0, y1;
  bool empty;  ///< nothing to show: the range is the unit square
  double X(double v) const { return ml + (v - x0) / (x1 - x0) * pw; }
  double Y(double v) const { return mt + ph - (v - y0) / (y1 - y0) * ph; }
};

// A y value on the chart's axis: log10 of it on a log axis (NaN, not drawn, when not positive).
double AxisY(const PlotChart& c, double v) {
  if (!c.y_log) return v;
  return v > 0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
}

// Every finite point of the fitted series, the x bands and the y bands; empty when none.
PlotRange DataExtent(const PlotChart& c, bool& empty) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : c.series) {
    if (!s.fits) continue;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      const double y = AxisY(c, s.y[i]);
      if (!std::isfinite(s.x[i]) || !std::isfinite(y)) continue;
      x0 = std::min(x0, s.x[i] - s.bar_width / 2);
      x1 = std::max(x1, s.x[i] + s.bar_width / 2);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  }
  for (const auto& b : c.bands) {
    x0 = std::min(x0, b.x0);
    x1 = std::max(x1, b.x1);
  }
  empty = !(x1 >= x0) || !(y1 >= y0);
  for (const auto& b : c.y_bands) {
    const double a = AxisY(c, b.x0), z = AxisY(c, b.x1);
    if (std::isfinite(a)) y0 = std::min(y0, a), y1 = std::max(y1, a);
    if (std::isfinite(z)) y0 = std::min(y0, z), y1 = std::max(y1, z);
  }
  if (empty) return {0, 1, 0, 1};
  return {x0, x1, y0, y1};
}

// The plot area of `c` in pixels (margins for the title, the ticks and the legend's rows).
PlotFrame AreaOf(const PlotChart& c) {
  const double W = c.width_px, H = c.height_px;
  const std::size_t entries = c.series.size() + (c.bands.empty() ? 0 : 1) + c.y_bands.size();
  const std::size_t columns = static_cast<std::size_t>(std::max(1, c.legend_columns));
  const double ml = 70, mr = 20, mt = 36;
  const double mb = 52 + 18.0 * static_cast<double>((entries + columns - 1) / columns);
  return {ml, mt, W - ml - mr, H - mt - mb, 0, 1, 0, 1, false};
}

// `range` when set, else every fitted point and band, padded (not yet widened for equal scales).
PlotRange PaddedRange(const PlotChart& c, bool& empty) {
  PlotRange r = DataExtent(c, empty);
  if (c.range) {
    r = *c.range;
    if (c.y_log)
      r.y0 = std::log10(std::max(r.y0, 1e-300)), r.y1 = std::log10(std::max(r.y1, 1e-300));
    empty = false;
    return r;
  }
  if (c.y_from_zero && !c.y_log) r.y0 = std::min(0.0, r.y0);
  if (r.x1 - r.x0 < 1e-9) r.x0 -= 0.5, r.x1 += 0.5;
  if (r.y1 - r.y0 < 1e-9) r.y0 -= 0.5, r.y1 += 0.5;
  const double padx = (r.x1 - r.x0) * 0.03, pady = (r.y1 - r.y0) * 0.05;
  r.x0 -= padx, r.x1 += padx, r.y1 += pady;
  if (!c.y_from_zero || c.y_log) r.y0 -= pady;
  return r;
}

// The frame of `c`: its range, or every fitted point and band, padded (equal scales when asked).
PlotFrame FitFrame(const PlotChart& c) {
  PlotFrame f = AreaOf(c);
  bool empty = false;
  PlotRange r = PaddedRange(c, empty);
  if (c.equal_aspect) {
    const double sx = (r.x1 - r.x0) / f.pw, sy = (r.y1 - r.y0) / f.ph, s = std::max(sx, sy);
    const double cx = (r.x0 + r.x1) / 2, cy = (r.y0 + r.y1) / 2;
    r = {cx - s * f.pw / 2, cx + s * f.pw / 2, cy - s * f.ph / 2, cy + s * f.ph / 2};
  }
  f.x0 = r.x0, f.x1 = r.x1, f.y0 = r.y0, f.y1 = r.y1, f.empty = empty;
  return f;
}

// One series: a polyline, points or bars, clipped to the plot area by the caller's group.
void WriteSeries(std::ostream& o, const PlotChart& c, const PlotSeries& s, const PlotFrame& f) {
  const double y0 = f.y0;
  const auto X = [&](double v) { return f.X(v); };
  const auto Y = [&](double v) { return f.Y(AxisY(c, v)); };
  const std::size_t n = std::min(s.x.size(), s.y.size());
  if (s.style == PlotSeries::Style::kLine && n > 0) {
    o << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\""
      << SvgNum(s.line_width_px) << "\" points=\"";
    for (std::size_t i = 0; i < n; ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(Y(s.y[i])))
        o << SvgNum(X(s.x[i])) << "," << SvgNum(Y(s.y[i])) << " ";
    }
    o << "\"/>\n";
  } else if (s.style == PlotSeries::Style::kPoints) {
    for (std::size_t i = 0; i < n; ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(Y(s.y[i]))) {
        o << "<circle cx=\"" << SvgNum(X(s.x[i])) << "\" cy=\"" << SvgNum(Y(s.y[i]))
          << "\" r=\"2\" fill=\"" << s.color << "\" fill-opacity=\"0.7\"/>\n";
      }
    }
  } else if (s.style == PlotSeries::Style::kBars) {
    for (std::size_t i = 0; i < n; ++i) {
      const double xa = X(s.x[i] - s.bar_width / 2), xb = X(s.x[i] + s.bar_width / 2);
      const double ya = f.Y(std::max(s.y[i], y0)), yb = f.Y(std::max(0.0, y0));
      o << "<rect x=\"" << SvgNum(xa) << "\" y=\"" << SvgNum(ya) << "\" width=\""
        << SvgNum(std::max(0.5, xb - xa - 1)) << "\" height=\"" << SvgNum(std::max(0.0, yb - ya))
        << "\" fill=\"" << s.color << "\"/>\n";
    }
  }
}

}  // namespace

namespace {

// A tick's label on a log axis: the value 10^v.
std::string LogTickLabel(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", std::pow(10.0, v));
  return b;
}

// Tick positions of the y axis: powers of ten on a log axis spanning a decade or more.
std::vector<double> YTicks(const PlotChart& c, const PlotFrame& f) {
  if (!c.y_log || f.y1 - f.y0 < 1) return NiceTicks(f.y0, f.y1, 6);
  std::vector<double> t;
  const double step = std::max(1.0, std::ceil((f.y1 - f.y0) / 8));
  for (double v = std::ceil(f.y0 / step) * step; v <= f.y1 + 1e-9; v += step) t.push_back(v);
  return t;
}

// Shaded x bands (outages), y bands (a χ² band) and outlined boxes, inside the plot area.
void WriteBands(std::ostream& o, const PlotChart& c, const PlotFrame& f) {
  for (const auto& b : c.bands) {
    const double xa = std::clamp(f.X(b.x0), f.ml, f.ml + f.pw);
    const double xb = std::clamp(f.X(b.x1), f.ml, f.ml + f.pw);
    o << "<rect class=\"xband\" x=\"" << SvgNum(xa) << "\" y=\"" << SvgNum(f.mt) << "\" width=\""
      << SvgNum(xb - xa) << "\" height=\"" << SvgNum(f.ph) << "\" fill=\"" << b.color
      << "\" fill-opacity=\"0.35\"><title>" << XmlEscape(b.label) << "</title></rect>\n";
  }
  for (const auto& b : c.y_bands) {
    const double lo = std::isfinite(AxisY(c, b.x0)) ? AxisY(c, b.x0) : f.y0;
    const double ya = std::clamp(f.Y(AxisY(c, b.x1)), f.mt, f.mt + f.ph);
    const double yb = std::clamp(f.Y(lo), f.mt, f.mt + f.ph);
    o << "<rect class=\"yband\" x=\"" << SvgNum(f.ml) << "\" y=\"" << SvgNum(ya) << "\" width=\""
      << SvgNum(f.pw) << "\" height=\"" << SvgNum(yb - ya) << "\" fill=\"" << b.color
      << "\" fill-opacity=\"0.25\"><title>" << XmlEscape(b.label) << "</title></rect>\n";
  }
}

// Outlined boxes, each at least kMinBoxPx on a side around its centre (a zoom's box on a large
// map still shows where it is), labelled beside it on the side with more room, the label on a
// white halo so that it reads over the tracks.
void WriteBoxes(std::ostream& o, const PlotChart& c, const PlotFrame& f) {
  constexpr double kMinBoxPx = 14;
  for (const auto& b : c.boxes) {
    double xa = f.X(b.range.x0), xb = f.X(b.range.x1);
    double ya = f.Y(AxisY(c, b.range.y1)), yb = f.Y(AxisY(c, b.range.y0));
    const double cx = (xa + xb) / 2, cy = (ya + yb) / 2;
    const double hw = std::max(kMinBoxPx, xb - xa) / 2, hh = std::max(kMinBoxPx, yb - ya) / 2;
    xa = cx - hw, xb = cx + hw, ya = cy - hh, yb = cy + hh;
    const bool left = cx > f.ml + f.pw / 2;
    o << "<rect class=\"box\" x=\"" << SvgNum(xa) << "\" y=\"" << SvgNum(ya) << "\" width=\""
      << SvgNum(xb - xa) << "\" height=\"" << SvgNum(yb - ya)
      << "\" fill=\"none\" stroke=\"#9467bd\" stroke-width=\"2\" stroke-dasharray=\"5,3\"/>"
      << "<text class=\"box-label\" x=\"" << SvgNum(left ? xa - 6 : xb + 6) << "\" y=\""
      << SvgNum(cy + 4) << "\" text-anchor=\"" << (left ? "end" : "start")
      << "\" fill=\"#6a3d9a\" font-weight=\"bold\" stroke=\"white\" stroke-width=\"4\" "
         "stroke-linejoin=\"round\" paint-order=\"stroke\">"
      << XmlEscape(b.label) << "</text>\n";
  }
}

// Grid lines and tick labels of both axes, the frame and the axis labels.
void WriteAxes(std::ostream& o, const PlotChart& c, const PlotFrame& f) {
  const auto xt = NiceTicks(f.x0, f.x1, 8), yt = YTicks(c, f);
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1, ystep = yt.size() > 1 ? yt[1] - yt[0] : 1;
  for (const double v : xt) {
    o << "<line x1=\"" << SvgNum(f.X(v)) << "\" y1=\"" << SvgNum(f.mt) << "\" x2=\""
      << SvgNum(f.X(v)) << "\" y2=\"" << SvgNum(f.mt + f.ph)
      << "\" stroke=\"#e0e0e0\"/>\n<text x=\"" << SvgNum(f.X(v)) << "\" y=\""
      << SvgNum(f.mt + f.ph + 16) << "\" text-anchor=\"middle\">" << TickLabel(v, xstep)
      << "</text>\n";
  }
  for (const double v : yt) {
    o << "<line x1=\"" << SvgNum(f.ml) << "\" y1=\"" << SvgNum(f.Y(v)) << "\" x2=\""
      << SvgNum(f.ml + f.pw) << "\" y2=\"" << SvgNum(f.Y(v))
      << "\" stroke=\"#e0e0e0\"/>\n<text x=\"" << SvgNum(f.ml - 6) << "\" y=\""
      << SvgNum(f.Y(v) + 4) << "\" text-anchor=\"end\">"
      << (c.y_log && f.y1 - f.y0 >= 1 ? LogTickLabel(v) : TickLabel(v, ystep)) << "</text>\n";
  }
  o << "<rect x=\"" << SvgNum(f.ml) << "\" y=\"" << SvgNum(f.mt) << "\" width=\"" << SvgNum(f.pw)
    << "\" height=\"" << SvgNum(f.ph) << "\" fill=\"none\" stroke=\"#444\"/>\n";
  o << "<text x=\"" << SvgNum(f.ml + f.pw / 2) << "\" y=\"" << SvgNum(f.mt + f.ph + 34)
    << "\" text-anchor=\"middle\">" << XmlEscape(c.x_label) << "</text>\n";
  o << "<text transform=\"translate(16," << SvgNum(f.mt + f.ph / 2)
    << ") rotate(-90)\" text-anchor=\"middle\">" << XmlEscape(c.y_label) << "</text>\n";
}

// The legend below the axis label, legend_columns entries per row; the x bands' entry last.
void WriteLegend(std::ostream& o, const PlotChart& c, const PlotFrame& f) {
  const std::size_t columns = static_cast<std::size_t>(std::max(1, c.legend_columns));
  const auto entry = [&](std::size_t i, const std::string& color, const std::string& label) {
    const double lx = f.ml +
                      static_cast<double>(i % columns) * (f.pw / static_cast<double>(columns)),
                 ly = f.mt + f.ph + 52 + static_cast<double>(i / columns) * 18;
    o << "<rect x=\"" << SvgNum(lx) << "\" y=\"" << SvgNum(ly - 9)
      << "\" width=\"14\" height=\"10\" fill=\"" << color << "\"/><text x=\"" << SvgNum(lx + 20)
      << "\" y=\"" << SvgNum(ly) << "\">" << XmlEscape(label) << "</text>\n";
  };
  for (std::size_t i = 0; i < c.series.size(); ++i) entry(i, c.series[i].color, c.series[i].label);
  std::size_t i = c.series.size();
  if (!c.bands.empty()) entry(i++, c.bands.front().color, c.band_legend);
  for (const auto& b : c.y_bands) entry(i++, b.color, b.label);
}

}  // namespace

void FitSizeToData(PlotChart& c, const PlotSizeLimits& limits) {
  bool empty = false;
  const PlotRange r = PaddedRange(c, empty);
  if (empty) return;
  PlotFrame f = AreaOf(c);
  const double aspect = (r.y1 - r.y0) / (r.x1 - r.x0);  // plot height per plot width
  double pw = f.pw;
  const double ph = std::clamp(pw * aspect, limits.min_plot_height_px, limits.max_plot_height_px);
  if (pw * aspect > limits.max_plot_height_px) {  // taller than allowed: narrower instead
    pw = std::max(limits.min_plot_width_px, limits.max_plot_height_px / aspect);
    if (pw < limits.two_columns_below_px) c.legend_columns = 2;
    if (pw < limits.one_column_below_px) c.legend_columns = 1;
    f = AreaOf(c);  // the legend's rows may have changed the bottom margin
  }
  c.width_px = static_cast<int>(std::ceil(pw + (c.width_px - f.pw)));
  c.height_px = static_cast<int>(std::ceil(ph + (c.height_px - f.ph)));
}

PlotRange ChartRange(const PlotChart& c) {
  const PlotFrame f = FitFrame(c);
  return {f.x0, f.x1, f.y0, f.y1};
}

std::string RenderSvg(const PlotChart& c) {
  const PlotFrame f = FitFrame(c);
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << c.width_px << "\" height=\""
    << c.height_px << "\" viewBox=\"0 0 " << c.width_px << " " << c.height_px
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o << "<text x=\"" << SvgNum(c.width_px / 2.0) << "\" y=\"22\" text-anchor=\"middle\" "
    << "font-size=\"15\">" << XmlEscape(c.title) << "</text>\n";
  o << "<defs><clipPath id=\"" << XmlEscape(c.id) << "\"><rect x=\"" << SvgNum(f.ml) << "\" y=\""
    << SvgNum(f.mt) << "\" width=\"" << SvgNum(f.pw) << "\" height=\"" << SvgNum(f.ph)
    << "\"/></clipPath></defs>\n";
  WriteBands(o, c, f);
  WriteAxes(o, c, f);
  if (f.empty) {
    o << "<text x=\"" << SvgNum(f.ml + f.pw / 2) << "\" y=\"" << SvgNum(f.mt + f.ph / 2)
      << "\" text-anchor=\"middle\" fill=\"#888\">" << XmlEscape(c.empty_note) << "</text>\n";
  }
  o << "<g clip-path=\"url(#" << XmlEscape(c.id) << ")\">\n";
  for (const auto& s : c.series) WriteSeries(o, c, s, f);
  WriteBoxes(o, c, f);
  o << "</g>\n";
  WriteLegend(o, c, f);
  o << "</svg>\n";
  return o.str();
}

}  // namespace hil::harness

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

// The frame of `c`: every finite point and every band, padded (equal scales when asked for).
PlotFrame FitFrame(const PlotChart& c) {
  const double W = c.width_px, H = c.height_px;
  const double ml = 70, mr = 20, mt = 36,
               mb = 52 + 18.0 * static_cast<double>((c.series.size() + 2) / 3);
  const double pw = W - ml - mr, ph = H - mt - mb;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : c.series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i] - s.bar_width / 2);
      x1 = std::max(x1, s.x[i] + s.bar_width / 2);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  }
  for (const auto& b : c.bands) {
    x0 = std::min(x0, b.x0);
    x1 = std::max(x1, b.x1);
  }
  const bool empty = !(x1 >= x0) || !(y1 >= y0);
  if (empty) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (c.y_from_zero) y0 = std::min(0.0, y0);
  if (x1 - x0 < 1e-9) x0 -= 0.5, x1 += 0.5;
  if (y1 - y0 < 1e-9) y0 -= 0.5, y1 += 0.5;
  const double padx = (x1 - x0) * 0.03, pady = (y1 - y0) * 0.05;
  x0 -= padx, x1 += padx, y1 += pady;
  if (!c.y_from_zero) y0 -= pady;
  if (c.equal_aspect) {
    const double sx = (x1 - x0) / pw, sy = (y1 - y0) / ph, s = std::max(sx, sy);
    const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    x0 = cx - s * pw / 2, x1 = cx + s * pw / 2, y0 = cy - s * ph / 2, y1 = cy + s * ph / 2;
  }
  return {ml, mt, pw, ph, x0, x1, y0, y1, empty};
}

// One series: a polyline, points or bars, clipped to the plot area by the caller's group.
void WriteSeries(std::ostream& o, const PlotSeries& s, const PlotFrame& f) {
  const double y0 = f.y0;
  const auto X = [&](double v) { return f.X(v); };
  const auto Y = [&](double v) { return f.Y(v); };
  const std::size_t n = std::min(s.x.size(), s.y.size());
  if (s.style == PlotSeries::Style::kLine && n > 0) {
    o << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"1.6\" points=\"";
    for (std::size_t i = 0; i < n; ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
        o << SvgNum(X(s.x[i])) << "," << SvgNum(Y(s.y[i])) << " ";
    }
    o << "\"/>\n";
  } else if (s.style == PlotSeries::Style::kPoints) {
    for (std::size_t i = 0; i < n; ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
        o << "<circle cx=\"" << SvgNum(X(s.x[i])) << "\" cy=\"" << SvgNum(Y(s.y[i]))
          << "\" r=\"2\" fill=\"" << s.color << "\" fill-opacity=\"0.7\"/>\n";
      }
    }
  } else if (s.style == PlotSeries::Style::kBars) {
    for (std::size_t i = 0; i < n; ++i) {
      const double xa = X(s.x[i] - s.bar_width / 2), xb = X(s.x[i] + s.bar_width / 2);
      const double ya = Y(std::max(s.y[i], y0)), yb = Y(std::max(0.0, y0));
      o << "<rect x=\"" << SvgNum(xa) << "\" y=\"" << SvgNum(ya) << "\" width=\""
        << SvgNum(std::max(0.5, xb - xa - 1)) << "\" height=\"" << SvgNum(std::max(0.0, yb - ya))
        << "\" fill=\"" << s.color << "\"/>\n";
    }
  }
}

}  // namespace

std::string RenderSvg(const PlotChart& c) {
  const PlotFrame frame = FitFrame(c);
  const double W = c.width_px;
  const double ml = frame.ml, mt = frame.mt, pw = frame.pw, ph = frame.ph;
  const double x0 = frame.x0, x1 = frame.x1, y0 = frame.y0, y1 = frame.y1;
  const bool empty = frame.empty;
  const auto X = [&](double v) { return frame.X(v); };
  const auto Y = [&](double v) { return frame.Y(v); };

  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << c.width_px << "\" height=\""
    << c.height_px << "\" viewBox=\"0 0 " << c.width_px << " " << c.height_px
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o << "<text x=\"" << SvgNum(W / 2) << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
    << XmlEscape(c.title) << "</text>\n";
  o << "<defs><clipPath id=\"plot\"><rect x=\"" << SvgNum(ml) << "\" y=\"" << SvgNum(mt)
    << "\" width=\"" << SvgNum(pw) << "\" height=\"" << SvgNum(ph) << "\"/></clipPath></defs>\n";
  for (const auto& b : c.bands) {
    o << "<rect x=\"" << SvgNum(X(b.x0)) << "\" y=\"" << SvgNum(mt) << "\" width=\""
      << SvgNum(X(b.x1) - X(b.x0)) << "\" height=\"" << SvgNum(ph)
      << "\" fill=\"#f4b183\" fill-opacity=\"0.35\"><title>" << XmlEscape(b.label)
      << "</title></rect>\n";
  }
  const auto xt = NiceTicks(x0, x1, 8), yt = NiceTicks(y0, y1, 6);
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1, ystep = yt.size() > 1 ? yt[1] - yt[0] : 1;
  for (const double v : xt) {
    o << "<line x1=\"" << SvgNum(X(v)) << "\" y1=\"" << SvgNum(mt) << "\" x2=\"" << SvgNum(X(v))
      << "\" y2=\"" << SvgNum(mt + ph) << "\" stroke=\"#e0e0e0\"/>\n<text x=\"" << SvgNum(X(v))
      << "\" y=\"" << SvgNum(mt + ph + 16) << "\" text-anchor=\"middle\">" << TickLabel(v, xstep)
      << "</text>\n";
  }
  for (const double v : yt) {
    o << "<line x1=\"" << SvgNum(ml) << "\" y1=\"" << SvgNum(Y(v)) << "\" x2=\"" << SvgNum(ml + pw)
      << "\" y2=\"" << SvgNum(Y(v)) << "\" stroke=\"#e0e0e0\"/>\n<text x=\"" << SvgNum(ml - 6)
      << "\" y=\"" << SvgNum(Y(v) + 4) << "\" text-anchor=\"end\">" << TickLabel(v, ystep)
      << "</text>\n";
  }
  o << "<rect x=\"" << SvgNum(ml) << "\" y=\"" << SvgNum(mt) << "\" width=\"" << SvgNum(pw)
    << "\" height=\"" << SvgNum(ph) << "\" fill=\"none\" stroke=\"#444\"/>\n";
  o << "<text x=\"" << SvgNum(ml + pw / 2) << "\" y=\"" << SvgNum(mt + ph + 34)
    << "\" text-anchor=\"middle\">" << XmlEscape(c.x_label) << "</text>\n";
  o << "<text transform=\"translate(16," << SvgNum(mt + ph / 2)
    << ") rotate(-90)\" text-anchor=\"middle\">" << XmlEscape(c.y_label) << "</text>\n";
  if (empty) {
    o << "<text x=\"" << SvgNum(ml + pw / 2) << "\" y=\"" << SvgNum(mt + ph / 2)
      << "\" text-anchor=\"middle\" fill=\"#888\">" << XmlEscape(c.empty_note) << "</text>\n";
  }
  o << "<g clip-path=\"url(#plot)\">\n";
  for (const auto& s : c.series) WriteSeries(o, s, frame);
  o << "</g>\n";
  // legend below the axis label, three entries per row
  for (std::size_t i = 0; i < c.series.size(); ++i) {
    const double lx = ml + static_cast<double>(i % 3) * (pw / 3),
                 ly = mt + ph + 52 + static_cast<double>(i / 3) * 18;
    o << "<rect x=\"" << SvgNum(lx) << "\" y=\"" << SvgNum(ly - 9)
      << "\" width=\"14\" height=\"10\" fill=\"" << c.series[i].color << "\"/><text x=\""
      << SvgNum(lx + 20) << "\" y=\"" << SvgNum(ly) << "\">" << XmlEscape(c.series[i].label)
      << "</text>\n";
  }
  if (!c.bands.empty()) {
    const double lx = ml + static_cast<double>(c.series.size() % 3) * (pw / 3),
                 ly = mt + ph + 52 + static_cast<double>(c.series.size() / 3) * 18;
    o << "<rect x=\"" << SvgNum(lx) << "\" y=\"" << SvgNum(ly - 9)
      << "\" width=\"14\" height=\"10\" fill=\"#f4b183\"/>"
      << "<text x=\"" << SvgNum(lx + 20) << "\" y=\"" << SvgNum(ly) << "\">GNSS outage</text>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace hil::harness

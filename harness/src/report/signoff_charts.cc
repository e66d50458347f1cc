// The sign-off report's charts (signoff_charts.h), from the report and its plot series.
#include "hil/harness/report/signoff_charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "hil/harness/report/report_plot_blocks.h"

namespace hil::harness {
namespace {

constexpr const char* kZoomColor = "#9467bd";

PlotSeries PointsAgainstTime(const std::string& label, const char* color,
                             const std::vector<ErrorSample>& errors, PlotSeries::Style style,
                             double (*value)(const ErrorSample&)) {
  PlotSeries s = NamedSeries(label, color, style);
  for (const ErrorSample& e : errors) {
    const double v = value(e);
    if (std::isfinite(v)) s.x.push_back(ToSeconds(e.t)), s.y.push_back(v);
  }
  return s;
}

// A moving mean of (x, y) over windows of `window` in x, evaluated at each point.
PlotSeries MovingMean(const PlotSeries& in, double window, const std::string& label,
                      const char* color) {
  PlotSeries out = NamedSeries(label, color);
  std::size_t lo = 0;
  double sum = 0;
  for (std::size_t hi = 0; hi < in.x.size(); ++hi) {
    sum += in.y[hi];
    while (in.x[hi] - in.x[lo] > window) sum -= in.y[lo++];
    if (in.x[hi] - in.x.front() < window / 2) continue;  // a full half window first
    out.x.push_back(in.x[hi] - window / 2);
    out.y.push_back(sum / static_cast<double>(hi - lo + 1));
  }
  return out;
}

}  // namespace

std::optional<WorstSegment> FindWorstSegment(const ReportSeries& s) {
  if (s.estimate_errors.empty()) return std::nullopt;
  const auto worst = std::max_element(
      s.estimate_errors.begin(), s.estimate_errors.end(),
      [](const ErrorSample& a, const ErrorSample& b) { return a.horizontal() < b.horizontal(); });
  WorstSegment w;
  w.t_worst_s = ToSeconds(worst->t);
  w.error_m = worst->horizontal();
  w.truth_en_m = worst->truth_enu_m.head<2>();
  w.estimate_en_m = worst->est_enu_m.head<2>();
  const Eigen::Vector2d c = (w.truth_en_m + w.estimate_en_m) / 2;
  const double half = std::max(kZoomMinHalfM, kZoomErrors * w.error_m);
  w.range = {c.x() - half, c.x() + half, c.y() - half, c.y() + half};
  return w;
}

std::vector<double> DistanceTravelled(const ReportSeries& s, const std::vector<double>& t_s) {
  std::vector<double> along(s.truth_en_m.size(), 0.0);
  for (std::size_t i = 1; i < along.size(); ++i)
    along[i] = along[i - 1] + (s.truth_en_m[i] - s.truth_en_m[i - 1]).norm();
  std::vector<double> d;
  d.reserve(t_s.size());
  for (const double t : t_s) {
    const auto it = std::upper_bound(s.truth_t_s.begin(), s.truth_t_s.end(), t);
    if (it == s.truth_t_s.begin() || along.empty()) {
      d.push_back(0);
      continue;
    }
    const std::size_t i = static_cast<std::size_t>(it - s.truth_t_s.begin()) - 1;
    if (i + 1 >= along.size()) {
      d.push_back(along.back());
      continue;
    }
    const double f = (t - s.truth_t_s[i]) / (s.truth_t_s[i + 1] - s.truth_t_s[i]);
    d.push_back(along[i] + f * (along[i + 1] - along[i]));
  }
  return d;
}

PlotChart MapChart(const RunReport& r, const ReportSeries& s) {
  PlotChart c;
  c.id = "map";
  c.title = "Map (local ENU at the scenario origin, equal axes)";
  c.x_label = "east (m)";
  c.y_label = "north (m)";
  c.equal_aspect = true;
  c.width_px = 900, c.height_px = 620;
  PlotSeries path = EnSeries(r.tracking ? "planned path" : "planned path (the scenario's)",
                             kPathColor, s.path_en_m);
  path.fits = false;  // drawn where the vehicle went; its margin beyond the run is clipped
  path.line_width_px = 3.0;
  c.series = {
      path, EnSeries("truth", kTruthColor, s.truth_en_m),
      EstimatedEnSeries("raw GNSS fixes", kGnssColor, s.fix_errors, PlotSeries::Style::kPoints),
      EstimatedEnSeries("estimate", kEstimateColor, s.estimate_errors)};
  if (const auto w = FindWorstSegment(s)) {
    char label[96];
    std::snprintf(label, sizeof label, "zoom: worst %.2f m at t = %.1f s", w->error_m,
                  w->t_worst_s);
    c.boxes.push_back({w->range, label});
  }
  FitSizeToData(c);  // the frame takes the field's shape: a long narrow field is drawn tall
  return c;
}

std::optional<PlotChart> WorstSegmentChart(const ReportSeries& s) {
  const auto w = FindWorstSegment(s);
  if (!w) return std::nullopt;
  PlotChart c;
  c.id = "zoom";
  char title[160];
  std::snprintf(title, sizeof title, "Zoom on the largest horizontal error: %.3f m at t = %.1f s",
                w->error_m, w->t_worst_s);
  c.title = title;
  c.x_label = "east (m)";
  c.y_label = "north (m)";
  c.equal_aspect = true;
  c.range = w->range;
  c.width_px = 900, c.height_px = 520;
  PlotSeries path = EnSeries("planned path", kPathColor, s.path_en_m);
  path.line_width_px = 3.0;
  PlotSeries worst = NamedSeries("largest error: truth to estimate", kZoomColor);
  worst.x = {w->truth_en_m.x(), w->estimate_en_m.x()};
  worst.y = {w->truth_en_m.y(), w->estimate_en_m.y()};
  worst.line_width_px = 2.5;
  PlotSeries estimate_points = EstimatedEnSeries("estimate (each solution)", kEstimateColor,
                                                 s.estimate_errors, PlotSeries::Style::kPoints);
  c.series = {
      path,
      EnSeries("truth", kTruthColor, s.truth_en_m),
      EstimatedEnSeries("raw GNSS fixes", kGnssColor, s.fix_errors, PlotSeries::Style::kPoints),
      EstimatedEnSeries("estimate", kEstimateColor, s.estimate_errors),
      estimate_points,
      worst};
  return c;
}

PlotChart CrossTrackChart(const RunReport& r, const ReportSeries& s) {
  PlotChart c;
  c.id = "xte";
  c.title = r.tracking ? "Cross-track error against distance"
                       : "Cross-track error of the estimate against distance (open loop)";
  c.x_label = r.tracking ? "distance (m): along the path (vehicle), travelled (estimate, fixes)"
                         : "distance travelled (m)";
  c.y_label = "cross-track error, + left (m)";
  c.empty_note = "no data: no scored solution";
  if (r.tracking) {
    PlotSeries t = NamedSeries("vehicle (truth) - path", kTruthColor);
    t.x = r.tracking->s_m;
    t.y = r.tracking->xte_m;
    c.series.push_back(t);
  }
  for (const auto& [label, color, errors] :
       {std::tuple{"estimate - truth", kEstimateColor, &s.estimate_errors},
        std::tuple{"raw GNSS fixes - truth", kGnssColor, &s.fix_errors}}) {
    std::vector<double> t_s, xte;
    for (const ErrorSample& e : *errors) {
      if (e.xte_m) t_s.push_back(ToSeconds(e.t)), xte.push_back(*e.xte_m);
    }
    PlotSeries x = NamedSeries(
        label, color,
        errors == &s.fix_errors ? PlotSeries::Style::kPoints : PlotSeries::Style::kLine);
    x.x = DistanceTravelled(s, t_s);
    x.y = xte;
    c.series.push_back(x);
  }
  return c;
}

PlotChart ErrorTimeChart(const RunReport& r, const ReportSeries& s) {
  PlotChart c;
  c.id = "error_time";
  c.title = "Horizontal error against time (GNSS outages shaded)";
  c.x_label = "time (s)";
  c.y_label = "horizontal error (m)";
  c.y_from_zero = true;
  for (const auto& o : r.outages) {
    char label[64];
    std::snprintf(label, sizeof label, "GNSS outage %.1f-%.1f s", o.start_s, o.end_s);
    c.bands.push_back({o.start_s, o.end_s, label});
  }
  const auto h = [](const ErrorSample& e) { return e.horizontal(); };
  c.series = {
      PointsAgainstTime("raw GNSS fixes", kGnssColor, s.fix_errors, PlotSeries::Style::kPoints, h),
      PointsAgainstTime("estimate", kEstimateColor, s.estimate_errors, PlotSeries::Style::kLine,
                        h)};
  return c;
}

PlotChart NeesChart(const ReportSeries& s) {
  PlotChart c;
  c.id = "nees";
  c.title = "Horizontal NEES against time (2 DOF, log scale) with its chi-square bands";
  c.x_label = "time (s)";
  c.y_label = "NEES, east and north";
  c.y_log = true;
  c.empty_note = "no data: the estimator reports no position sigma (pos_std_enu_m)";
  const auto nees = [](const ErrorSample& e) {
    return e.nees_horizontal ? *e.nees_horizontal : std::numeric_limits<double>::quiet_NaN();
  };
  PlotSeries samples = PointsAgainstTime("NEES of each solution", kEstimateColor, s.estimate_errors,
                                         PlotSeries::Style::kPoints, nees);
  if (samples.x.empty()) return c;
  c.y_bands = {
      {kNeesSampleLow, kNeesSampleHigh, "99 % of single samples when consistent", "#c7e9c0"},
      {kNeesMeanLow, kNeesMeanHigh, "99 % band of a 10-sample mean", "#41ab5d"}};
  PlotSeries mean = MovingMean(samples, kNeesMeanWindowS, "10 s moving mean", "#08306b");
  mean.line_width_px = 2.2;
  c.series = {samples, mean};
  return c;
}

}  // namespace hil::harness

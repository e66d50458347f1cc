// Closed loop's plots in report.html: the planned path with the truth and the estimate, the
// truth's cross-track error against the distance along the path, and the commanded against the
// actual steering (a differential-drive base: yaw rate; a steering ECU: road-wheel angle) at each
// control tick.
#include <fstream>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "hil/harness/report/report_html.h"
#include "hil/harness/report/report_plot_blocks.h"

namespace hil::harness {

std::optional<PlotChart> SteeringChart(const ReportSeries& s) {
  const bool yaw = !s.commanded_yaw_rate_dps.empty();
  if (!yaw && s.commanded_steer_deg.empty()) return std::nullopt;
  PlotChart c;
  c.id = "steering";
  c.title = yaw ? "Steering: commanded against actual yaw rate (control ticks)"
                : "Steering: commanded against actual road-wheel angle (control ticks)";
  c.x_label = "time (s)";
  c.y_label = yaw ? "yaw rate, + left (deg/s)" : "road-wheel angle, + left (deg)";
  PlotSeries cmd = NamedSeries("commanded", "#d62728"), act = NamedSeries("actual", "#1f77b4");
  cmd.x = s.tick_t_s;
  cmd.y = yaw ? s.commanded_yaw_rate_dps : s.commanded_steer_deg;
  act.x = s.tick_t_s;
  act.y = yaw ? s.actual_yaw_rate_dps : s.actual_steer_deg;
  c.series = {cmd, act};
  return c;
}

void WriteClosedLoopPlots(const RunReport& r, const ReportSeries& s, const std::string& dir,
                          std::vector<std::string>& files) {
  {
    PlotChart c;
    c.title = "Planned path, truth and estimate (local ENU)";
    c.x_label = "east (m)";
    c.y_label = "north (m)";
    c.equal_aspect = true;
    c.series = {EnSeries("planned path", kPathColor, s.path_en_m),
                EnSeries("truth", kTruthColor, s.truth_en_m),
                EstimatedEnSeries("estimate", kEstimateColor, s.estimate_errors)};
    WritePlot(c, dir, "plots/closed_loop_path.svg", files);
  }
  {
    PlotChart c;
    c.title = "Cross-track error of the truth against the distance along the path";
    c.x_label = "distance along the path (m)";
    c.y_label = "cross-track, + left (m)";
    PlotSeries x = NamedSeries("truth XTE", kTruthColor);
    x.x = r.tracking->s_m;
    x.y = r.tracking->xte_m;
    c.series = {x};
    WritePlot(c, dir, "plots/cross_track.svg", files);
  }
  if (const auto steering = SteeringChart(s))
    WritePlot(*steering, dir, "plots/steering.svg", files);
}

}  // namespace hil::harness

// Closed loop's plots in report.html: the planned path with the truth and the estimate, the
// truth's cross-track error against the distance along the path, and the commanded against the
// actual steering (a differential-drive base: yaw rate) at each control tick.
#include <fstream>
#include <numbers>
#include <stdexcept>

#include "hil/harness/report/report_html.h"
#include "hil/harness/report/report_plot_blocks.h"

namespace hil::harness {

PlotChart SteeringChart(const ReportSeries& s) {
  PlotChart c;
  c.id = "steering";
  c.title = "Steering: commanded against actual yaw rate (control ticks)";
  c.x_label = "time (s)";
  c.y_label = "yaw rate, + left (deg/s)";
  PlotSeries cmd = NamedSeries("commanded", "#d62728"), act = NamedSeries("actual", "#1f77b4");
  cmd.x = s.tick_t_s;
  cmd.y = s.commanded_yaw_rate_dps;
  act.x = s.tick_t_s;
  act.y = s.actual_yaw_rate_dps;
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
  WritePlot(SteeringChart(s), dir, "plots/steering.svg", files);
}

}  // namespace hil::harness

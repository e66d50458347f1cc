// Closed loop's plots in report.html: the planned path with the truth and the estimate, the
// truth's cross-track error against the distance along the path, and the commanded against the
// actual steering (a differential-drive base: yaw rate) at each control tick.
#include <fstream>
#include <numbers>
#include <stdexcept>

#include "hil/harness/report/output_file.h"
#include "hil/harness/report/report_html.h"
#include "hil/harness/report/svg_plot.h"

namespace hil::harness {
namespace {

void Write(const std::string& path, const std::string& text) { WriteOutputFile(path, text); }

PlotSeries NamedSeries(const char* label, const char* color) {
  return {label, color, PlotSeries::Style::kLine, {}, {}, 0};
}

}  // namespace

void WriteClosedLoopPlots(const RunReport& r, const ReportSeries& s, const std::string& dir,
                          std::vector<std::string>& files) {
  {
    PlotChart c;
    c.title = "Planned path, truth and estimate (local ENU)";
    c.x_label = "east (m)";
    c.y_label = "north (m)";
    c.equal_aspect = true;
    PlotSeries path = NamedSeries("planned path", "#2ca02c"),
               truth = NamedSeries("truth", "#222222"), est = NamedSeries("estimate", "#1f77b4");
    for (const auto& p : s.path_en_m) path.x.push_back(p.x()), path.y.push_back(p.y());
    for (const auto& p : s.truth_en_m) truth.x.push_back(p.x()), truth.y.push_back(p.y());
    for (const auto& e : s.estimate_errors)
      est.x.push_back(e.est_enu_m.x()), est.y.push_back(e.est_enu_m.y());
    c.series = {path, truth, est};
    Write(dir + "/plots/closed_loop_path.svg", RenderSvg(c));
    files.push_back("plots/closed_loop_path.svg");
  }
  {
    PlotChart c;
    c.title = "Cross-track error of the truth against the distance along the path";
    c.x_label = "distance along the path (m)";
    c.y_label = "cross-track, + left (m)";
    PlotSeries x = NamedSeries("truth XTE", "#222222");
    x.x = r.tracking->s_m;
    x.y = r.tracking->xte_m;
    c.series = {x};
    Write(dir + "/plots/cross_track.svg", RenderSvg(c));
    files.push_back("plots/cross_track.svg");
  }
  {
    PlotChart c;
    c.title = "Steering: commanded against actual yaw rate (control ticks)";
    c.x_label = "time (s)";
    c.y_label = "yaw rate, + left (deg/s)";
    PlotSeries cmd = NamedSeries("commanded", "#d62728"), act = NamedSeries("actual", "#1f77b4");
    cmd.x = s.tick_t_s;
    cmd.y = s.commanded_yaw_rate_dps;
    act.x = s.tick_t_s;
    act.y = s.actual_yaw_rate_dps;
    c.series = {cmd, act};
    Write(dir + "/plots/steering.svg", RenderSvg(c));
    files.push_back("plots/steering.svg");
  }
}

}  // namespace hil::harness

#include "hil/harness/report/report_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "hil/harness/report/output_file.h"
#include "hil/harness/report/pass_to_pass_report.h"
#include "hil/harness/report/report_plot_blocks.h"
#include "hil/harness/report/signoff_charts.h"
#include "hil/harness/report/signoff_sections.h"
#include "hil/harness/report/svg_plot.h"

namespace hil::harness {
namespace {

std::string Fmt(const std::optional<double>& v, const char* unit = "") {
  if (!v) return "n/a";
  char b[64];
  std::snprintf(b, sizeof b, "%.3f%s", *v, unit);
  return b;
}

PlotSeries Cdf(const std::vector<std::pair<double, double>>& cdf, const std::string& label,
               const char* color) {
  PlotSeries s = NamedSeries(label, color);
  for (const auto& [x, y] : cdf) s.x.push_back(x), s.y.push_back(y);
  return s;
}

}  // namespace

// The latency histogram (real-time and scaled runs: `latency_ms` is empty in virtual mode).
PlotChart LatencyChart(const ReportSeries& s) {
  PlotChart c;
  c.id = "latency";
  c.title = "Output latency (arrival wall time - time of validity)";
  c.x_label = "latency (ms)";
  c.y_label = "solutions";
  c.y_from_zero = true;
  const double lo = s.latency_ms.min(), hi = std::max(s.latency_ms.max(), lo + 1e-3);
  const int bins =
      std::clamp(static_cast<int>(std::sqrt(static_cast<double>(s.latency_ms.count()))) + 1, 5, 40);
  const double w = (hi - lo) / bins;
  PlotSeries h{"solutions per bin", kEstimateColor, PlotSeries::Style::kBars, {}, {}, w};
  std::vector<double> count(static_cast<std::size_t>(bins), 0.0);
  s.latency_ms.ForEach([&](double v, std::uint64_t n) {
    count[static_cast<std::size_t>(std::clamp(static_cast<int>((v - lo) / w), 0, bins - 1))] +=
        static_cast<double>(n);
  });
  for (int i = 0; i < bins; ++i) {
    h.x.push_back(lo + (i + 0.5) * w);
    h.y.push_back(count[static_cast<std::size_t>(i)]);
  }
  c.series = {h};
  return c;
}

namespace {

// The GNSS outages table: per outage its maximum error, error growth and reconvergence.
void AppendOutagesHtml(std::string& h, const RunReport& r) {
  char buf[512];
  if (!r.outages.empty()) {
    h += "<h2>GNSS outages</h2>\n<table><tr><th>start (s)</th><th>end (s)</th><th>max horizontal "
         "error</th>"
         "<th>error growth</th><th>reconvergence time</th></tr>\n";
    for (const auto& o : r.outages) {
      std::string growth;
      for (const auto& [t, e] : o.growth) {
        std::snprintf(buf, sizeof buf, "%s%.0f s: %.2f m", growth.empty() ? "" : ", ", t, e);
        growth += buf;
      }
      std::snprintf(buf, sizeof buf, "<tr><td>%.1f</td><td>%.1f</td><td>%s</td>", o.start_s,
                    o.end_s,
                    o.samples ? Fmt(o.max_horizontal_error_m, " m").c_str() : "no solutions");
      h += buf;
      h += "<td>" + growth + "</td><td>" + Fmt(o.reconvergence_time_s, " s") + "</td></tr>\n";
    }
    h += "</table>\n";
  }
}

// navd's health: the flags it raised and its non-zero counters.
void AppendHealthHtml(std::string& h, const RunReport& r) {
  if (r.estimator_health.present) {
    h += "<h2>Estimator health (navd)</h2>\n<p>Flags raised:";
    for (const std::string& f : r.estimator_health.flags_seen) h += " " + XmlEscape(f);
    if (r.estimator_health.flags_seen.empty()) h += " none";
    h += "</p>\n<p>Counters:";
    for (const auto& [k, v] : r.estimator_health.counters) {
      if (v != 0) h += " " + XmlEscape(k) + "=" + std::to_string(static_cast<long long>(v));
    }
    h += "</p>\n";
  }
}

// Renders `chart` into RUN_DIR/`file` and inline into the page, under a caption.
void Figure(std::string& h, const PlotChart& chart, const std::string& dir, const std::string& file,
            const std::string& caption) {
  const std::string svg = RenderSvg(chart);
  WriteOutputFile(dir + "/" + file, svg);
  h += "<figure id=\"fig-" + chart.id + "\">" + svg + "<figcaption>" + caption + " <a href=\"" +
       file + "\">" + file + "</a></figcaption></figure>\n";
}

// The accuracy table, each estimate figure beside the raw fixes'; figures outside their band
// (ReviewFlags) stand out.
void AppendAccuracyHtml(std::string& h, const RunReport& r) {
  std::map<std::string, bool> flagged;  // metric → severe
  for (const ReviewFlag& f : ReviewFlags(r)) flagged[f.metric] = f.severe;
  h += "<section><h2>Accuracy against truth</h2>\n<table><tr><th>metric</th><th>estimate</th>"
       "<th>raw GNSS fixes</th></tr>\n";
  const MetricTable est = AccuracyTable(r.metrics), raw = AccuracyTable(r.baselines);
  for (const auto& [name, v] : est) {
    const auto it = raw.find(name);
    const auto flag = flagged.find(name);
    h += "<tr><td>" + name + "</td><td" +
         (flag == flagged.end() ? ""
          : flag->second        ? " class=\"flagged\""
                                : " class=\"flagged-note\"") +
         ">" + Fmt(v) + "</td><td>" + Fmt(it == raw.end() ? std::nullopt : it->second) +
         "</td></tr>\n";
  }
  char buf[160];
  std::snprintf(buf, sizeof buf, "<tr><td>samples</td><td>%zu</td><td>%zu</td></tr>\n",
                r.metrics.samples, r.baselines.samples);
  h += buf;
  std::snprintf(buf, sizeof buf,
                "<tr><td>output rate</td><td>%.3f Hz</td><td></td></tr><tr><td>missing "
                "solutions</td><td>%.1f %%</td><td></td></tr>\n",
                r.output_rate_hz, 100.0 * r.timing.missing_fraction);
  h += buf;
  h += "</table>\n<p>Cross-track error: signed distance to the planned path (a polyline, "
       "interpolated between vertices as ISO 12188-2 expects), estimate minus truth at the same "
       "time of validity.</p></section>\n";
}

// Closed loop on ISO 11783-7: what the steering ECU and its transport saw.
void AppendSteeringEcuHtml(std::string& h, const SteeringEcuReport& e) {
  char buf[768];
  std::snprintf(buf, sizeof buf,
                "<h3>Steering ECU (ISO 11783-7 over %s)</h3>\n<table class=\"kv\">"
                "<tr><th>guidance frames from the controller / lost</th><td>%llu / %llu</td></tr>"
                "<tr><th>commands accepted / refused (length, source, range)</th>"
                "<td>%llu / %llu, %llu, %llu</td></tr>"
                "<tr><th>engagements / engaged at the end</th><td>%llu / %s</td></tr>"
                "<tr><th>watchdog trips</th><td%s>%llu</td></tr>"
                "<tr><th>last exit reason</th><td%s>%s</td></tr>"
                "<tr><th>road-wheel angle RMS error (actual - target)</th><td>%.3f deg</td></tr>"
                "</table>\n",
                XmlEscape(e.transport).c_str(),
                static_cast<unsigned long long>(e.frames_from_controller),
                static_cast<unsigned long long>(e.frames_lost),
                static_cast<unsigned long long>(e.commands_accepted),
                static_cast<unsigned long long>(e.wrong_length),
                static_cast<unsigned long long>(e.unknown_source),
                static_cast<unsigned long long>(e.out_of_range),
                static_cast<unsigned long long>(e.engagements), e.engaged ? "yes" : "no",
                e.watchdog_trips > 0 ? " class=\"flagged\"" : "",
                static_cast<unsigned long long>(e.watchdog_trips),
                e.exit_reason_code != 0 ? " class=\"flagged-note\"" : "",
                XmlEscape(e.exit_reason).c_str(), e.commanded_steer_rms_error_deg);
  h += buf;
}

// Closed loop: what the controller and the actuator did.
void AppendClosedLoopHtml(std::string& h, const RunReport& r) {
  if (!r.closed_loop) return;
  const ClosedLoopReport& c = *r.closed_loop;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "<section><h2>Closed loop: controller and actuator</h2>\n<table class=\"kv\">"
                "<tr><th>controller</th><td>%s</td></tr>"
                "<tr><th>control ticks</th><td>%llu</td></tr>"
                "<tr><th>ticks without a fresh command</th><td%s>%llu</td></tr>"
                "<tr><th>motor commands / invalid lines</th><td>%llu / %llu</td></tr>"
                "<tr><th>watchdog trips</th><td%s>%llu</td></tr>"
                "<tr><th>final speed</th><td>%.3f m/s (%s)</td></tr></table>",
                XmlEscape(c.controller_exit).c_str(),
                static_cast<unsigned long long>(c.control_ticks),
                c.missing_commands > 0 ? " class=\"flagged\"" : "",
                static_cast<unsigned long long>(c.missing_commands),
                static_cast<unsigned long long>(c.motor_commands),
                static_cast<unsigned long long>(c.invalid_lines),
                c.watchdog_trips > 0 ? " class=\"flagged\"" : "",
                static_cast<unsigned long long>(c.watchdog_trips), c.final_speed_mps,
                c.stopped ? "stopped" : "moving");
  h += buf;
  if (c.steering_ecu) AppendSteeringEcuHtml(h, *c.steering_ecu);
  h += "</section>\n";
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1000px;margin:1.5em auto;color:#222;font-size:14px}"
    "h1{margin:0 0 .2em}h2{border-bottom:2px solid #ddd;padding-bottom:2px;margin-top:1.6em}"
    "table{border-collapse:collapse;margin:.6em 0}td,th{border:1px solid #ccc;padding:3px 8px;"
    "text-align:left;vertical-align:top}table.kv>tbody>tr>th{background:#f4f4f4;width:13em}"
    "table.inner td,table.inner th{border:1px solid #ddd;padding:1px 6px;background:#fff}"
    "a.review{color:#b00020;font-weight:bold}.pass{color:#176317;font-weight:bold}.fail{color:#"
    "b00020;font-weight:bold}"
    ".verdict{display:inline-block;font-size:28px;padding:4px 18px;border:3px solid;"
    "border-radius:6px;margin:.2em 0}"
    "tr.flag-severe td{background:#fde7ea}tr.flag-note td{background:#fff4d6}"
    "td.flagged{background:#b00020!important;color:#fff;font-weight:bold}"
    "td.flagged-note{background:#e69f00!important;color:#000;font-weight:bold}"
    "figure{margin:1em 0;page-break-inside:avoid;break-inside:avoid}"
    "figure svg{max-width:100%;height:auto;border:1px solid "
    "#ddd}figcaption{font-size:12px;color:#555}"
    "section{page-break-inside:auto}.sign td{height:2.4em;width:20em}"
    "@media print{body{max-width:none;margin:0;font-size:11px}a{color:inherit}"
    "h2{page-break-after:avoid;break-after:avoid}}";

// The charts of the page, each inline and in RUN_DIR/plots.
void AppendFiguresHtml(std::string& h, const RunReport& r, const ReportSeries& s,
                       const std::string& dir) {
  std::filesystem::create_directories(dir + "/plots");
  h += "<section><h2>Map</h2>\n";
  Figure(h, MapChart(r, s), dir, "plots/trajectory.svg",
         "Equal axes fitted to the truth, the estimate and the raw fixes; the planned path is "
         "drawn where they are. The dashed box is the zoom below.");
  if (const auto zoom = WorstSegmentChart(s))
    Figure(h, *zoom, dir, "plots/worst_segment.svg",
           "Around the largest horizontal error (a square of side four times that error, at "
           "least 0.1 m); the purple segment joins the truth and the estimate at that time.");
  h += "</section><section><h2>Cross-track error over distance</h2>\n";
  Figure(h, CrossTrackChart(r, s), dir, "plots/cross_track_distance.svg",
         r.tracking ? "The vehicle's signed distance from the planned path (what the controller "
                      "achieved) and the estimate's cross-track error (what guidance acted on)."
                    : "Open loop: the estimate's and the raw fixes' cross-track error against the "
                      "scenario's planned path, minus the truth's.");
  h += "</section><section><h2>Error against time</h2>\n";
  Figure(h, ErrorTimeChart(r, s), dir, "plots/horizontal_error.svg",
         "GNSS outages shaded (hover for their times).");
  h += "</section><section><h2>Consistency: NEES over time</h2>\n";
  Figure(h, NeesChart(s), dir, "plots/nees.svg",
         "Pale green: where 99 % of single samples of a consistent 2-DOF NEES lie (0.01 to 10.6); "
         "dark green: the 99 % band of a mean over 10 independent samples (0.74 to 4.0), which "
         "the moving mean should stay in. Above: the reported sigma is over-confident.");
  PlotChart cdf;
  cdf.id = "cdf";
  cdf.title = "Empirical CDF of the horizontal error";
  cdf.x_label = "horizontal error (m)";
  cdf.y_label = "samples at or below (%)";
  cdf.y_from_zero = true;
  cdf.series = {Cdf(s.fix_cdf, "raw GNSS fixes", kGnssColor),
                Cdf(s.estimate_cdf, "estimate", kEstimateColor)};
  Figure(h, cdf, dir, "plots/error_cdf.svg", "");
  if (r.tracking) {
    if (const auto steering = SteeringChart(s)) Figure(h, *steering, dir, "plots/steering.svg", "");
    std::vector<std::string> files;
    WriteClosedLoopPlots(r, s, dir, files);  // the closed loop's own plot files
  }
  h += "</section>\n";
}

void AppendArtefactsAndSignature(std::string& h) {
  h += "<section><h2>Artefacts</h2>\n<ul>";
  for (const char* f : {"report.json", "junit.xml", "truth.csv", "estimate.csv", "gnss_fixes.csv",
                        "captures/", "plots/", "estimator.stderr"}) {
    h += std::string("<li><a href=\"") + f + "\">" + f + "</a></li>";
  }
  h += "</ul></section>\n<section><h2>Sign-off</h2>\n<table class=\"sign\">"
       "<tr><th>tested by</th><td></td><th>signature</th><td></td></tr>"
       "<tr><th>reviewed by</th><td></td><th>date</th><td></td></tr></table></section>\n";
}

}  // namespace

void WriteReportHtml(const RunReport& r, const ReportSeries& s, const RunHeader& header,
                     const std::string& dir) {
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>hil sign-off "
       "report: " +
       XmlEscape(r.scenario) + "</title>\n<style>" + kStyle + "</style></head><body>\n";
  h += "<h1>Sign-off report: " + XmlEscape(r.scenario) + " <span class=\"" +
       (r.pass() ? "pass\">PASS" : "fail\">FAIL") + "</span></h1>\n";
  AppendRunHeaderHtml(h, r, header);
  AppendVerdictHtml(h, r);
  AppendReviewHtml(h, r);
  AppendFiguresHtml(h, r, s, dir);
  AppendAccuracyHtml(h, r);
  AppendClosedLoopHtml(h, r);
  if (r.pass_to_pass) AppendPassToPassHtml(h, *r.pass_to_pass);
  if (r.rtk_rover) {
    AppendRtkRoverHtml(h, *r.rtk_rover);
    Figure(h, RtkTimelineChart(*r.rtk_rover, r.sim_time_s), dir, "plots/rtk_timeline.svg",
           "The rover's RTK state over the run (report.json rtk_rover.timeline).");
  }
  AppendOutagesHtml(h, r);
  AppendFaultEffectsHtml(h, r, s);
  AppendHealthHtml(h, r);
  AppendHarnessHtml(h, r, header);
  if (s.latency_ms.count() > 0) {
    if (r.latency) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "<p>Latency p50 / p99 / max: %.2f / %.2f / %.2f ms.</p>\n",
                    r.latency->p50_ms, r.latency->p99_ms, r.latency->max_ms);
      h += buf;
    }
    Figure(h, LatencyChart(s), dir, "plots/latency_histogram.svg", "");
  }
  AppendArtefactsAndSignature(h);
  h += "</body></html>\n";
  WriteOutputFile(dir + "/report.html", h);
}

}  // namespace hil::harness

#include "hil/harness/report/report_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "hil/harness/report/output_file.h"
#include "hil/harness/report/pass_to_pass_report.h"
#include "hil/harness/report/report_plot_blocks.h"
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

std::vector<PlotBand> OutageBands(const RunReport& r) {
  std::vector<PlotBand> b;
  for (const auto& o : r.outages) {
    char label[64];
    std::snprintf(label, sizeof label, "GNSS outage %.1f-%.1f s", o.start_s, o.end_s);
    b.push_back({o.start_s, o.end_s, label});
  }
  return b;
}

}  // namespace

std::vector<std::string> WritePlots(const RunReport& r, const ReportSeries& s,
                                    const std::string& dir) {
  std::filesystem::create_directories(dir + "/plots");
  std::vector<std::string> files;
  {
    PlotChart c;
    c.title = "Trajectory (local ENU at the scenario origin)";
    c.x_label = "east (m)";
    c.y_label = "north (m)";
    c.equal_aspect = true;
    c.series = {
        EnSeries("truth", kTruthColor, s.truth_en_m),
        EstimatedEnSeries("raw GNSS fixes", kGnssColor, s.fix_errors, PlotSeries::Style::kPoints),
        EstimatedEnSeries("estimate", kEstimateColor, s.estimate_errors)};
    WritePlot(c, dir, "plots/trajectory.svg", files);
  }
  {
    PlotChart c;
    c.title = "Horizontal error against time";
    c.x_label = "time (s)";
    c.y_label = "horizontal error (m)";
    c.y_from_zero = true;
    c.bands = OutageBands(r);
    PlotSeries gnss = NamedSeries("raw GNSS fixes", kGnssColor, PlotSeries::Style::kPoints);
    for (const auto& e : s.fix_errors)
      gnss.x.push_back(ToSeconds(e.t)), gnss.y.push_back(e.horizontal());
    PlotSeries est = NamedSeries("estimate", kEstimateColor);
    for (const auto& e : s.estimate_errors)
      est.x.push_back(ToSeconds(e.t)), est.y.push_back(e.horizontal());
    c.series = {gnss, est};
    WritePlot(c, dir, "plots/horizontal_error.svg", files);
  }
  {
    PlotChart c;
    c.title = "Empirical CDF of the horizontal error";
    c.x_label = "horizontal error (m)";
    c.y_label = "samples at or below (%)";
    c.y_from_zero = true;
    c.series = {Cdf(s.fix_cdf, "raw GNSS fixes", kGnssColor),
                Cdf(s.estimate_cdf, "estimate", kEstimateColor)};
    WritePlot(c, dir, "plots/error_cdf.svg", files);
  }
  {
    PlotChart c;
    c.title = "Output latency (arrival wall time - time of validity)";
    c.x_label = "latency (ms)";
    c.y_label = "solutions";
    c.y_from_zero = true;
    c.empty_note =
        "no data: latency is measured in real-time and scaled runs (--mode realtime|scaled)";
    if (s.latency_ms.count() > 0) {
      const double lo = s.latency_ms.min(), hi = std::max(s.latency_ms.max(), lo + 1e-3);
      const int bins = std::clamp(
          static_cast<int>(std::sqrt(static_cast<double>(s.latency_ms.count()))) + 1, 5, 40);
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
    }
    WritePlot(c, dir, "plots/latency_histogram.svg", files);
  }
  if (r.tracking) WriteClosedLoopPlots(r, s, dir, files);
  return files;
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

// The fault timeline and the table of what was injected, when, and the recovery.
void AppendFaultsHtml(std::string& h, const RunReport& r) {
  char buf[512];
  if (!r.faults.empty()) {
    h += "<h2>Fault timeline</h2>\n<ul>\n";
    for (const auto& [kind, when] : r.faults)
      h += "<li>" + XmlEscape(kind) + ": " + XmlEscape(when) + "</li>\n";
    std::snprintf(buf, sizeof buf,
                  "</ul><p>Injected: %llu messages dropped, %llu bytes corrupted.</p>\n",
                  static_cast<unsigned long long>(r.fault_messages_dropped),
                  static_cast<unsigned long long>(r.fault_bytes_corrupted));
    h += buf;
    h += "<table><tr><th>fault</th><th>link</th><th>window s</th><th>injected</th><th>first–last "
         "s</th>"
         "<th>recovery</th></tr>\n";
    for (const FaultInjection& f : r.fault_injections) {
      std::snprintf(buf, sizeof buf,
                    "<tr><td>%s</td><td>%s</td><td>%.1f–%.1f</td><td>%llu "
                    "%s</td><td>%s</td><td>%s</td></tr>\n",
                    XmlEscape(f.kind).c_str(), f.link.empty() ? "all" : XmlEscape(f.link).c_str(),
                    f.start_s, f.end_s, static_cast<unsigned long long>(f.count),
                    XmlEscape(f.unit).c_str(),
                    f.times_s.empty()
                        ? "–"
                        : (Fmt(f.times_s.front(), "") + "–" + Fmt(f.times_s.back(), "")).c_str(),
                    Fmt(f.recovery_time_s, " s").c_str());
      h += buf;
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

void AppendVerdictHtml(std::string& h, const RunReport& r) {
  char buf[64];
  h += "<h2>Verdict</h2>\n<table><tr><th>criterion</th><th>threshold</th><th>value</th><th>result</"
       "th></tr>\n";
  for (const auto& c : r.criteria) {
    std::snprintf(buf, sizeof buf, "%.4g", c.threshold);
    h += "<tr><td>" + XmlEscape(c.name) + "</td><td>" + buf + "</td><td>" + Fmt(c.value) +
         "</td><td class=\"" + (c.pass ? "pass\">PASS" : "fail\">FAIL") + "</td></tr>\n";
  }
  for (const auto& p : r.problems)
    h += "<tr><td colspan=\"3\">" + XmlEscape(p) + "</td><td class=\"fail\">FAIL</td></tr>\n";
  h += "</table>\n";
  h += "<p>Default criteria (every run is judged on them unless its scenario's "
       "<code>default_criteria:</code> says otherwise):</p>\n<table><tr><th>key</th><th>metric</"
       "th><th>status</th><th>bound or reason</th></tr>\n";
  for (const auto& d : r.default_criteria)
    h += "<tr><td>" + XmlEscape(d.key) + "</td><td>" + XmlEscape(d.metric) + "</td><td>" +
         XmlEscape(d.status) + "</td><td>" + XmlEscape(d.detail) + "</td></tr>\n";
  h += "</table>\n";
}

}  // namespace

void WriteReportHtml(const RunReport& r, const ReportSeries& s, const std::string& dir) {
  const std::vector<std::string> plots = WritePlots(r, s, dir);
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>hil run: " +
       XmlEscape(r.scenario) +
       "</title>\n<style>body{font-family:sans-serif;max-width:1000px;margin:2em auto;color:#222}"
       "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:4px "
       "10px;text-align:left}"
       ".pass{color:#176317;font-weight:bold}.fail{color:#b00020;font-weight:bold}img{max-width:"
       "100%;"
       "border:1px solid #ddd;margin:0.5em 0}</style></head><body>\n";
  h += "<h1>" + XmlEscape(r.scenario) + ": <span class=\"" +
       (r.pass() ? "pass\">PASS" : "fail\">FAIL") + "</span></h1>\n";
  char buf[512];
  std::snprintf(
      buf, sizeof buf,
      "<p>Scenario file %s, seed %llu, %s mode (speed %.2fx), %.1f s simulated in %.2f s.</p>\n",
      XmlEscape(r.scenario_file).c_str(), static_cast<unsigned long long>(r.seed), r.mode.c_str(),
      r.speed, r.sim_time_s, r.wall_time_s);
  h += buf;
  h += "<p>Estimator: <code>" + XmlEscape(r.estimator_command) + "</code> (output " +
       XmlEscape(r.estimator_output) + ", " + XmlEscape(r.estimator_exit) + ").</p>\n";
  AppendVerdictHtml(h, r);
  h += "<h2>Accuracy against truth</h2>\n<table><tr><th>metric</th><th>estimate</th><th>raw "
       "GNSS</th></tr>\n";
  const MetricTable est = AccuracyTable(r.metrics), raw = AccuracyTable(r.baselines);
  for (const auto& [name, v] : est) {
    const auto it = raw.find(name);
    h += "<tr><td>" + name + "</td><td>" + Fmt(v) + "</td><td>" +
         Fmt(it == raw.end() ? std::nullopt : it->second) + "</td></tr>\n";
  }
  std::snprintf(buf, sizeof buf, "<tr><td>samples</td><td>%zu</td><td>%zu</td></tr>\n",
                r.metrics.samples, r.baselines.samples);
  h += buf;
  h += "</table>\n<p>Cross-track error: signed distance to the planned path (a polyline, "
       "interpolated between "
       "vertices as ISO 12188-2 expects), estimate minus truth at the same time of validity.</p>\n";
  h += "<h2>Timing</h2>\n<table>\n";
  std::snprintf(buf, sizeof buf,
                "<tr><td>output rate</td><td>%.3f Hz</td></tr><tr><td>missing "
                "solutions</td><td>%.1f %%</td></tr>\n",
                r.output_rate_hz, 100.0 * r.timing.missing_fraction);
  h += buf;
  if (r.latency) {
    std::snprintf(buf, sizeof buf,
                  "<tr><td>latency p50 / p99 / max</td><td>%.2f / %.2f / %.2f ms</td></tr>\n",
                  r.latency->p50_ms, r.latency->p99_ms, r.latency->max_ms);
    h += buf;
  }
  if (r.timing.jitter_p99_ms) {
    std::snprintf(
        buf, sizeof buf,
        "<tr><td>arrival jitter p50 / p99 / max</td><td>%.2f / %.2f / %.2f ms</td></tr>\n",
        *r.timing.jitter_p50_ms, *r.timing.jitter_p99_ms, *r.timing.jitter_max_ms);
    h += buf;
  }
  h += "</table>\n";
  if (r.pass_to_pass) AppendPassToPassHtml(h, *r.pass_to_pass);
  AppendOutagesHtml(h, r);
  AppendFaultsHtml(h, r);
  AppendHealthHtml(h, r);
  h += "<h2>Plots</h2>\n";
  for (const auto& p : plots) h += "<p><img src=\"" + p + "\" alt=\"" + p + "\"></p>\n";
  h += "<h2>Artefacts</h2>\n<ul>";
  for (const char* f : {"report.json", "junit.xml", "truth.csv", "estimate.csv", "gnss_fixes.csv",
                        "captures/", "estimator.stderr"}) {
    h += std::string("<li><a href=\"") + f + "\">" + f + "</a></li>";
  }
  h += "</ul>\n</body></html>\n";
  WriteOutputFile(dir + "/report.html", h);
}

}  // namespace hil::harness

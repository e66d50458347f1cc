// The sign-off report's faults with their effects and the harness's own figures
// (signoff_sections.h).
#include <algorithm>
#include <cstdio>

#include "hil/harness/report/signoff_sections.h"

namespace hil::harness {
namespace {

// The estimate's effect window after a fault ends: 10 s, the closed loop's default fault window
// (ClosedLoopSpec::fault_window_s), so open and closed loop read alike.
constexpr double kEffectWindowS = 10.0;

// The largest horizontal error of the estimate in [t0, t1], nullopt without a solution then.
std::optional<double> MaxErrorIn(const std::vector<ErrorSample>& errors, double t0, double t1) {
  std::optional<double> m;
  for (const ErrorSample& e : errors) {
    const double t = ToSeconds(e.t);
    if (t >= t0 && t <= t1) m = std::max(m.value_or(0.0), e.horizontal());
  }
  return m;
}

std::string PathEffect(const RunReport& r, std::size_t i) {
  if (!r.tracking || i >= r.tracking_faults.size()) return "";
  const FaultPathDeviation& d = r.tracking_faults[i];
  return "<td>" + FormatOptional(d.max_deviation_m, "%.3f", " m") +
         (d.max_deviation_s ? " at " + FormatNumber(*d.max_deviation_s, "%.1f") + " s" : "") +
         "</td>";
}

}  // namespace

void AppendFaultEffectsHtml(std::string& h, const RunReport& r, const ReportSeries& s) {
  h += "<section><h2>Faults injected and their effects</h2>\n";
  if (r.fault_injections.empty()) {
    h += "<p>No fault was injected in this run.</p></section>\n";
    return;
  }
  h += "<table><tr><th>fault</th><th>link</th><th>window (s)</th><th>injected</th>"
       "<th>first - last (s)</th><th>largest estimate error, start to end + " +
       FormatNumber(kEffectWindowS, "%.0f") + " s</th><th>recovery</th>";
  if (r.tracking) h += "<th>largest path deviation from its value at the start</th>";
  h += "</tr>\n";
  for (std::size_t i = 0; i < r.fault_injections.size(); ++i) {
    const FaultInjection& f = r.fault_injections[i];
    const std::optional<double> worst =
        MaxErrorIn(s.estimate_errors, f.start_s, f.end_s + kEffectWindowS);
    h += std::string("<tr") + (f.count == 0 ? " class=\"flag-note\"" : "") + "><td>" +
         XmlEscape(f.kind) + "</td><td>" + (f.link.empty() ? "all" : XmlEscape(f.link)) +
         "</td><td>" + FormatNumber(f.start_s, "%.1f") + " - " + FormatNumber(f.end_s, "%.1f") +
         "</td><td>" + std::to_string(static_cast<unsigned long long>(f.count)) + " " +
         XmlEscape(f.unit) + (f.count == 0 ? " (never injected)" : "") + "</td><td>" +
         (f.times_s.empty() ? "-"
                            : FormatNumber(f.times_s.front(), "%.1f") + " - " +
                                  FormatNumber(f.times_s.back(), "%.1f")) +
         "</td><td>" + FormatOptional(worst, "%.3f", " m") + "</td><td>" +
         FormatOptional(f.recovery_time_s, "%.1f", " s") + "</td>" + PathEffect(r, i) + "</tr>\n";
  }
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "</table><p>Byte faults in all: %llu messages dropped, %llu bytes corrupted.</p>\n",
                static_cast<unsigned long long>(r.fault_messages_dropped),
                static_cast<unsigned long long>(r.fault_bytes_corrupted));
  h += buf;
  h += "</section>\n";
}

void AppendHarnessHtml(std::string& h, const RunReport& r, const RunHeader& header) {
  h += "<section><h2>What the harness measured of itself</h2>\n<table class=\"kv\">\n";
  h += "<tr><th>bytes sent on the serial links</th><td>" +
       std::to_string(static_cast<unsigned long long>(r.gnss_bytes)) + "</td></tr>\n";
  h += "<tr><th>messages dropped by a full transmit buffer</th><td" +
       std::string(r.gnss_messages_dropped > 0 ? " class=\"flagged\"" : "") + ">" +
       std::to_string(static_cast<unsigned long long>(r.gnss_messages_dropped)) + "</td></tr>\n";
  if (r.closed_loop && r.closed_loop->stepping == "lockstep") {
    const ClosedLoopReport& c = *r.closed_loop;
    h += "<tr><th>lockstep actions served over 1 ms late</th><td>" +
         std::to_string(static_cast<unsigned long long>(c.late_actions)) + " of " +
         std::to_string(static_cast<unsigned long long>(c.paced_actions)) + " (largest " +
         FormatNumber(c.max_late_ms, "%.2f") + " ms)</td></tr>\n";
  }
  h += "</table>\n";
  if (header.stepping == "virtual") {
    h += "<p>Virtual mode: the run keeps no wall clock, so there is no schedule error, no output "
         "latency and no arrival jitter to measure; the latency chart does not apply. Run with "
         "<code>--mode realtime</code> or <code>--mode scaled</code> to measure them.</p>";
  } else if (header.links.empty()) {
    h += header.stepping == "lockstep"
             ? "<p>Lockstep: the links carry the virtual run's bytes, released in step with the "
               "host, so no byte has a wall-clock schedule to miss; the paced actions' lateness "
               "above is the harness's timing figure, the output latency below the "
               "estimator's.</p>"
             : "<p>No link carried a timed byte.</p>";
  } else {
    h += "<table><tr><th>link</th><th>timed</th><th>schedule error p50 / p99 / max (&micro;s)</th>"
         "<th>dropped unread</th></tr>\n";
    for (const HeaderLink& l : header.links) {
      h += "<tr><td>" + XmlEscape(l.name) + "</td><td>" +
           std::to_string(static_cast<unsigned long long>(l.units)) + " " + l.unit + "</td><td>" +
           FormatOptional(l.p50_us, "%.0f") + " / " + FormatOptional(l.p99_us, "%.0f") + " / " +
           FormatOptional(l.max_us, "%.0f") + "</td><td" +
           (l.bytes_dropped_unread > 0 ? " class=\"flagged\"" : "") + ">" +
           std::to_string(static_cast<unsigned long long>(l.bytes_dropped_unread)) + "</td></tr>\n";
    }
    h += "</table><p>Schedule error: the wall time a byte (a CAN frame) went out minus the wall "
         "time the emulation scheduled it for.</p>";
  }
  h += "</section>\n";
}

}  // namespace hil::harness

// The text sections of the sign-off report (signoff_sections.h).
#include "hil/harness/report/signoff_sections.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>

#include "hil/harness/scenario/default_criteria.h"

namespace hil::harness {
namespace {

// One row of a two-column table.
void Row(std::string& h, const std::string& key, const std::string& value_html) {
  h += "<tr><th>" + XmlEscape(key) + "</th><td>" + value_html + "</td></tr>\n";
}

// The metric a criterion's name starts with ("horizontal_rmse_m <= 1", "default fused_vs_raw: …").
std::string CriterionMetric(const CriterionResult& c) {
  if (!c.default_key.empty()) {
    const DefaultCriterionSpec* d = FindDefaultCriterion(c.default_key);
    return d ? d->metric : "";
  }
  return c.name.substr(0, c.name.find(' '));
}

std::string CriterionMeaning(const CriterionResult& c) {
  if (!c.default_key.empty()) {
    const DefaultCriterionSpec* d = FindDefaultCriterion(c.default_key);
    return d ? d->meaning : "";
  }
  return MetricMeaning(CriterionMetric(c));
}

// The accuracy figures compared with the raw fixes': the RMS and percentile ones (the largest
// error is not: the raw fixes have none during an outage, the estimate does).
constexpr const char* kComparedWithRaw[] = {"horizontal_rmse_m", "cep50_m",
                                            "cep95_m",           "vertical_rmse_m",
                                            "velocity_rmse_mps", "heading_rmse_deg"};

// A mean NEES against its 99 % band over 10 independent samples (default_criteria.h), with what
// the scenario says of the default criterion on it.
void FlagNees(const RunReport& r, std::vector<ReviewFlag>& flags, const char* metric,
              const std::optional<double>& v, double low, double high, int dof) {
  if (!v) return;
  std::string band = FormatNumber(low, "%.2f") + " to " + FormatNumber(high, "%.2f") + " (" +
                     std::to_string(dof) + " DOF, " + std::to_string(dof) +
                     " when consistent; 99 % band of a 10-sample mean)";
  if (*v > high)
    band += ": the reported sigma is over-confident";
  else if (*v < low)
    band += ": the reported sigma is conservative";
  else
    return;
  for (const DefaultCriterionStatus& d : r.default_criteria) {
    if (d.metric == metric && d.status != "judged" && d.status != "tightened")
      band += " (default criterion " + d.status + ": " + d.detail + ")";
  }
  flags.push_back({metric, *v, band, *v > high});
}

}  // namespace

std::string FormatNumber(double v, const char* format) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::string FormatOptional(const std::optional<double>& v, const char* format, const char* unit) {
  return v ? FormatNumber(*v, format) + unit : "n/a";
}

std::string MetricMeaning(const std::string& metric) {
  static const std::map<std::string, std::string> kMeaning = {
      {"horizontal_rmse_m", "root mean square of the horizontal error against truth (m)"},
      {"horizontal_rmse_to_raw", "the estimate's horizontal RMSE over the raw GNSS fixes'"},
      {"cep50_m", "median horizontal error (m)"},
      {"cep95_m", "95th percentile of the horizontal error (m)"},
      {"max_horizontal_error_m", "largest horizontal error of any solution (m)"},
      {"vertical_rmse_m", "root mean square of the height error (m)"},
      {"velocity_rmse_mps", "root mean square of the horizontal velocity error (m/s)"},
      {"heading_rmse_deg", "root mean square of the heading error (degrees)"},
      {"cross_track_rmse_m", "RMS of the estimate's cross-track error minus the truth's (m)"},
      {"cross_track_p95_m", "95th percentile of |cross-track error| (m)"},
      {"cross_track_max_m", "largest |cross-track error| (m)"},
      {"output_rate_hz", "solutions per second over the evaluated run"},
      {"max_lateral_deviation_m", "closed loop: largest distance of the vehicle from the path (m)"},
      {"max_heading_deviation_deg", "closed loop: largest heading off the path's direction (deg)"},
      {"latency_p99_ms", "99th percentile of arrival wall time minus time of validity (ms)"},
      {"jitter_p99_ms", "99th percentile of the spread of solution arrivals (ms)"},
      {"outage_max_horizontal_error_m", "largest horizontal error during a GNSS outage (m)"},
      {"reconvergence_time_s", "time after an outage until the error is back below its bound"},
      {"nees_mean", "mean NEES of the 3-D position (3 when the sigma is right)"},
      {"nees_horizontal_mean", "mean NEES of east and north (2 when the sigma is right)"},
      {"nees_vertical_mean", "mean NEES of the height (1 when the sigma is right)"},
      {"solutions_missing_fraction", "fraction of the expected solutions that never came"},
      {"fault_recovery_time_s", "time after a fault until the error is back below its bound"},
      {"fault_injections_min", "fewest injections of any scripted fault (it happened)"},
      {"outage_max_east_error_m", "largest east error during a GNSS outage (m)"},
      {"outage_max_north_error_m", "largest north error during a GNSS outage (m)"},
      {"outage_max_up_error_m", "largest height error during a GNSS outage (m)"},
      {"outage_max_enu_error_m", "largest 3-D error during a GNSS outage (m)"},
      {"closed_loop.missing_commands", "control ticks without a fresh controller command"},
      {"closed_loop.watchdog_trips", "times the base's watchdog stopped the motors"},
      {"closed_loop.final_speed_mps", "the vehicle's speed at the end of the run (m/s)"},
      {"closed_loop.distance_after_last_command_m", "distance driven after the last command (m)"},
      {"closed_loop.distance_after_watchdog_m", "distance driven after the watchdog tripped (m)"},
      {"closed_loop.command_bytes_lost", "controller bytes the command link lost"},
      {"tracking.cross_track_mean_abs_m", "mean |distance of the vehicle from the path| (m)"},
      {"tracking.cross_track_rmse_m", "RMS distance of the vehicle from the path (m)"},
      {"tracking.cross_track_p95_abs_m", "95th percentile of |vehicle to path| (m)"},
      {"tracking.cross_track_max_abs_m", "largest |vehicle to path| (m)"},
      {"tracking.heading_error_rms_deg", "RMS of the vehicle's heading off the path (deg)"},
      {"tracking.straight.cross_track_mean_abs_m", "mean |vehicle to path| on straights (m)"},
      {"tracking.straight.cross_track_p95_abs_m", "95th pct |vehicle to path| on straights (m)"},
      {"tracking.settling_distance_m", "distance until the vehicle settled on the path (m)"},
      {"tracking.settling_time_s", "time until the vehicle settled on the path (s)"},
      {"tracking.from_start_mean_abs_m", "mean |vehicle to path| from the start (m)"},
      {"tracking.from_start_max_abs_m", "largest |vehicle to path| from the start (m)"},
      {"tracking.stable_distance_m", "distance the vehicle stayed settled on the path (m)"},
      {"tracking.steady_state_mean_abs_m", "mean |vehicle to path| once settled (m)"},
      {"rtk_rover.fixed_fraction", "share of the RTK rover's epochs with a fixed solution"},
      {"rtk_rover.float_fraction", "share of the RTK rover's epochs with a float solution"},
      {"rtk_rover.time_to_first_float_s", "time until the rover's first RTK solution (s)"},
      {"rtk_rover.time_to_first_fixed_s", "time until the rover's first fixed solution (s)"},
      {"rtk_rover.fixed_losses", "times the rover fell from fixed to float or less"},
      {"rtk_rover.rtcm_crc_failed", "RTCM3 frames the rover rejected by their CRC-24Q"},
      {"rtk_rover.heading_valid_epochs", "moving-base epochs with a valid heading"},
      {"rtk_rover.heading_rms_error_deg", "RMS of the dual-antenna heading against truth (deg)"},
      {"rtk_rover.heading_max_error_deg", "largest dual-antenna heading error (deg)"},
  };
  const auto it = kMeaning.find(metric);
  if (it != kMeaning.end()) return it->second;
  if (metric.rfind("pass_to_pass.", 0) == 0)
    return "pass-to-pass cross-track error, ISO 12188-2 style (m)";
  return "";
}

std::vector<ReviewFlag> ReviewFlags(const RunReport& r) {
  std::vector<ReviewFlag> flags;
  FlagNees(r, flags, "nees_mean", r.metrics.nees_mean, 1.379, 5.367, 3);
  FlagNees(r, flags, "nees_horizontal_mean", r.metrics.nees_horizontal_mean, 0.7434, 4.0, 2);
  FlagNees(r, flags, "nees_vertical_mean", r.metrics.nees_vertical_mean, 0.2156, 2.52, 1);
  // against the raw fixes, with the fused_vs_raw bound the run was judged with (none when off)
  double factor = kWorseThanRawFactor;
  for (const DefaultCriterionStatus& d : r.default_criteria) {
    if (d.key != "fused_vs_raw") continue;
    if (d.status == "off") factor = 0;
    if (d.bound) factor = *d.bound;
  }
  const MetricTable est = AccuracyTable(r.metrics), raw = AccuracyTable(r.baselines);
  for (const char* name : kComparedWithRaw) {
    const auto e = est.find(name), b = raw.find(name);
    if (factor <= 0 || e == est.end() || b == raw.end() || !e->second || !b->second ||
        *b->second <= 0)
      continue;
    if (*e->second > factor * *b->second) {
      flags.push_back({name, *e->second,
                       "at most " + FormatNumber(factor, "%.2g") + " x the raw GNSS fixes' " +
                           FormatNumber(*b->second) + ": the estimate is worse than the raw fixes",
                       true});
    }
  }
  const auto heading = r.metrics.heading_rmse_deg;
  if (heading && *heading > kHeadingReviewDeg) {
    flags.push_back({"heading_rmse_deg", *heading,
                     "at most " + FormatNumber(kHeadingReviewDeg, "%.0f") +
                         " degrees (review bound of this report)",
                     true});
  }
  return flags;
}

std::string UtcText(UnixTime t) {
  const std::time_t s = static_cast<std::time_t>(ToNs(t) / 1000000000);
  std::tm tm{};
  gmtime_r(&s, &tm);
  char b[40];
  std::strftime(b, sizeof b, "%Y-%m-%d %H:%M:%S UTC", &tm);
  return b;
}

void AppendRunHeaderHtml(std::string& h, const RunReport& r, const RunHeader& header) {
  h += "<section class=\"header\"><h2>What was tested</h2>\n<table class=\"kv\">\n";
  Row(h, "scenario",
      "<b>" + XmlEscape(r.scenario) + "</b>" + (header.short_form ? " (--short form)" : ""));
  Row(h, "scenario file", "<code>" + XmlEscape(r.scenario_file) + "</code>");
  Row(h, "scenario SHA-256",
      header.scenario_sha256.empty() ? "n/a (no file: the embedded default)"
                                     : "<code>" + header.scenario_sha256 + "</code>");
  char site[200];
  std::snprintf(site, sizeof site,
                "origin %.7f&deg; N, %.7f&deg; E, height %.2f m above the WGS-84 ellipsoid "
                "(ellipsoidal, not above the geoid)",
                header.origin_lat_deg, header.origin_lon_deg, header.origin_height_m);
  Row(h, "site", site);
  Row(h, "date and time of the run", XmlEscape(header.run_started_utc));
  Row(h, "scenario time 0",
      XmlEscape(header.scenario_start_utc) + " (GNSS time the devices emulate)");
  std::string dev = "<table class=\"inner\"><tr><th>device</th><th>links</th><th>profile</th></tr>";
  for (const HeaderDevice& d : header.devices)
    dev += "<tr><td>" + XmlEscape(d.kind) + "</td><td>" + XmlEscape(d.links) + "</td><td>" +
           XmlEscape(d.profile) + "</td></tr>";
  Row(h, "devices", dev + "</table>");
  Row(h, "estimator under test",
      "<code>" + XmlEscape(r.estimator_command) + "</code><br>" +
          XmlEscape(header.estimator_build));
  if (!header.controller.empty())
    Row(h, "controller under test", "<code>" + XmlEscape(header.controller) + "</code>");
  Row(h, "hil",
      "version " + XmlEscape(header.hil_version) + ", commit <code>" +
          XmlEscape(header.hil_commit) + "</code>");
  Row(h, "machine",
      XmlEscape(header.cpu_model) + ", " + std::to_string(header.cpus_online) +
          " CPUs online; kernel " + XmlEscape(header.kernel));
  char mode[200];
  const std::string stepping = header.stepping == r.mode ? "" : " (" + header.stepping + ")";
  std::snprintf(mode, sizeof mode, "%s%s, speed %.2fx; %.1f s simulated in %.2f s wall time",
                r.mode.c_str(), stepping.c_str(), r.speed, r.sim_time_s, r.wall_time_s);
  Row(h, "mode", XmlEscape(mode));
  Row(h, "seed", std::to_string(static_cast<unsigned long long>(r.seed)));
  h += "</table></section>\n";
}

void AppendVerdictHtml(std::string& h, const RunReport& r) {
  std::size_t failed = 0;
  for (const auto& c : r.criteria) failed += c.pass ? 0 : 1;
  const std::size_t flags = ReviewFlags(r).size();  // a pass may still carry values to review
  h += "<section><h2>Verdict at a glance</h2>\n<p class=\"verdict " +
       std::string(r.pass() ? "pass\">PASS" : "fail\">FAIL") + "</p><p>" +
       std::to_string(r.criteria.size() - failed) + " of " + std::to_string(r.criteria.size()) +
       " criteria met; " + std::to_string(r.problems.size()) + " run problem(s); " +
       (flags == 0 ? std::string("no value outside its band")
                   : "<a class=\"review\" href=\"#review\">" + std::to_string(flags) +
                         " value(s) outside their band to review</a>") +
       ".</p>\n";
  h += "<table><tr><th>criterion</th><th>what it means</th><th>bound</th><th>value</th>"
       "<th>result</th></tr>\n";
  for (const auto& c : r.criteria) {
    h += std::string("<tr") + (c.pass ? "" : " class=\"flag-severe\"") + "><td>" +
         XmlEscape(c.name) + "</td><td>" + XmlEscape(CriterionMeaning(c)) + "</td><td>" +
         FormatNumber(c.threshold, "%.4g") + "</td><td>" + FormatOptional(c.value, "%.4g") +
         "</td><td class=\"" + (c.pass ? "pass\">PASS" : "fail\">FAIL") + "</td></tr>\n";
  }
  for (const auto& p : r.problems)
    h += "<tr class=\"flag-severe\"><td colspan=\"4\">run problem: " + XmlEscape(p) +
         "</td><td class=\"fail\">FAIL</td></tr>\n";
  h += "</table>\n<p>Default criteria judge every run unless its scenario's "
       "<code>default_criteria:</code> says otherwise:</p>\n<table><tr><th>key</th><th>metric</th>"
       "<th>what it means</th><th>status</th><th>bound or reason</th></tr>\n";
  for (const auto& d : r.default_criteria) {
    const DefaultCriterionSpec* spec = FindDefaultCriterion(d.key);
    h += "<tr><td>" + XmlEscape(d.key) + "</td><td>" + XmlEscape(d.metric) + "</td><td>" +
         XmlEscape(spec ? spec->meaning : "") + "</td><td>" + XmlEscape(d.status) + "</td><td>" +
         XmlEscape(d.detail) + "</td></tr>\n";
  }
  h += "</table></section>\n";
}

void AppendReviewHtml(std::string& h, const RunReport& r) {
  const std::vector<ReviewFlag> flags = ReviewFlags(r);
  h += "<section id=\"review\"><h2>Values outside their band</h2>\n";
  if (flags.empty()) {
    h += "<p>None: every mean NEES is inside its chi-square band, no accuracy figure is worse "
         "than the raw fixes' by more than " +
         FormatNumber(kWorseThanRawFactor, "%.1f") + " x, the heading RMSE is within " +
         FormatNumber(kHeadingReviewDeg, "%.0f") + " degrees.</p>";
  } else {
    h += "<table><tr><th>metric</th><th>value</th><th>expected band</th></tr>\n";
    for (const ReviewFlag& f : flags) {
      h += std::string("<tr class=\"") + (f.severe ? "flag-severe" : "flag-note") + "\"><td>" +
           XmlEscape(f.metric) + "</td><td class=\"" + (f.severe ? "flagged" : "flagged-note") +
           "\">" + FormatNumber(f.value, "%.4g") + "</td><td>" + XmlEscape(f.band) + "</td></tr>\n";
    }
    h += "</table>";
  }
  h += "</section>\n";
}

}  // namespace hil::harness

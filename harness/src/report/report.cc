#include "hil/harness/report/report.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "hil/harness/report/fixed_text.h"
#include "hil/harness/report/output_file.h"
#include "hil/harness/report/pass_to_pass_report.h"
#include "hil/harness/report/run_outputs.h"

namespace hil::harness {
namespace {

nlohmann::json OptionalJson(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json AccuracyJson(const AccuracyMetrics& m) {
  nlohmann::json j;
  j["samples"] = m.samples;
  j["horizontal_rmse_m"] =
      m.samples ? nlohmann::json(m.horizontal_rmse_m) : nlohmann::json(nullptr);
  j["cep50_m"] = m.samples ? nlohmann::json(m.cep50_m) : nlohmann::json(nullptr);
  j["cep95_m"] = m.samples ? nlohmann::json(m.cep95_m) : nlohmann::json(nullptr);
  j["max_horizontal_error_m"] =
      m.samples ? nlohmann::json(m.max_horizontal_error_m) : nlohmann::json(nullptr);
  j["vertical_rmse_m"] = m.samples ? nlohmann::json(m.vertical_rmse_m) : nlohmann::json(nullptr);
  j["velocity_rmse_mps"] = OptionalJson(m.velocity_rmse_mps);
  j["heading_rmse_deg"] = OptionalJson(m.heading_rmse_deg);
  j["cross_track_rmse_m"] = OptionalJson(m.cross_track_rmse_m);
  j["cross_track_p95_m"] = OptionalJson(m.cross_track_p95_m);
  j["cross_track_max_m"] = OptionalJson(m.cross_track_max_m);
  return j;
}

// Each outage's figures (null where no estimate fell inside it) and its error growth.
nlohmann::json OutagesJson(const std::vector<OutageMetrics>& outages) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& o : outages) {
    nlohmann::json growth = nlohmann::json::array();
    for (const auto& [h, e] : o.growth)
      growth.push_back({{"t_since_start_s", h}, {"horizontal_error_m", e}});
    a.push_back({{"start_s", o.start_s},
                 {"end_s", o.end_s},
                 {"samples", o.samples},
                 {"max_horizontal_error_m",
                  o.samples ? nlohmann::json(o.max_horizontal_error_m) : nlohmann::json(nullptr)},
                 {"max_east_error_m",
                  o.samples ? nlohmann::json(o.max_abs_error_enu_m.x()) : nlohmann::json(nullptr)},
                 {"max_north_error_m",
                  o.samples ? nlohmann::json(o.max_abs_error_enu_m.y()) : nlohmann::json(nullptr)},
                 {"max_up_error_m",
                  o.samples ? nlohmann::json(o.max_abs_error_enu_m.z()) : nlohmann::json(nullptr)},
                 {"reconvergence_time_s", OptionalJson(o.reconvergence_time_s)},
                 {"error_growth", growth}});
  }
  return a;
}

}  // namespace

std::string XmlEscape(const std::string& s) {
  std::string o;
  o.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '&':
        o += "&amp;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

bool RunReport::pass() const {
  if (!complete || !problems.empty()) return false;
  for (const auto& c : criteria) {
    if (!c.pass) return false;
  }
  return true;
}

MetricTable AccuracyTable(const AccuracyMetrics& m) {
  MetricTable t;
  const auto v = [&](double x) { return m.samples ? std::optional<double>(x) : std::nullopt; };
  t["horizontal_rmse_m"] = v(m.horizontal_rmse_m);
  t["cep50_m"] = v(m.cep50_m);
  t["cep95_m"] = v(m.cep95_m);
  t["max_horizontal_error_m"] = v(m.max_horizontal_error_m);
  t["vertical_rmse_m"] = v(m.vertical_rmse_m);
  t["velocity_rmse_mps"] = m.velocity_rmse_mps;
  t["heading_rmse_deg"] = m.heading_rmse_deg;
  t["cross_track_rmse_m"] = m.cross_track_rmse_m;
  t["cross_track_p95_m"] = m.cross_track_p95_m;
  t["cross_track_max_m"] = m.cross_track_max_m;
  t["nees_mean"] = m.nees_mean;
  t["nees_horizontal_mean"] = m.nees_horizontal_mean;
  t["nees_vertical_mean"] = m.nees_vertical_mean;
  return t;
}

MetricTable RunMetricTable(const RunReport& r) {
  MetricTable t = AccuracyTable(r.metrics);
  // the fused estimate's horizontal RMSE over the raw fixes' (a claim across seeds judges it)
  t["horizontal_rmse_to_raw"] =
      r.metrics.samples && r.baselines.samples && r.baselines.horizontal_rmse_m > 0
          ? std::optional<double>(r.metrics.horizontal_rmse_m / r.baselines.horizontal_rmse_m)
          : std::nullopt;
  if (r.tracking) {
    const XteStats& x = r.tracking->all;
    const bool any = x.samples > 0;
    const auto v = [any](double d) { return any ? std::optional<double>(d) : std::nullopt; };
    t["tracking.cross_track_mean_abs_m"] = v(x.mean_abs_m);
    t["tracking.cross_track_rmse_m"] = v(x.rmse_m);
    t["tracking.cross_track_p95_abs_m"] = v(x.p95_abs_m);
    t["tracking.cross_track_max_abs_m"] = v(x.max_abs_m);
    t["tracking.heading_error_rms_deg"] = v(x.heading_rmse_deg);
    const XteStats& st = r.tracking->straight;
    const auto vs = [&st](double d) {
      return st.samples > 0 ? std::optional<double>(d) : std::nullopt;
    };
    t["tracking.straight.cross_track_mean_abs_m"] = vs(st.mean_abs_m);
    t["tracking.straight.cross_track_p95_abs_m"] = vs(st.p95_abs_m);
    t["tracking.settling_distance_m"] = r.tracking->settling_distance_m;
    t["tracking.settling_time_s"] = r.tracking->settling_time_s;
    const XteStats& f = r.tracking->from_start;
    t["tracking.from_start_mean_abs_m"] =
        f.samples ? std::optional<double>(f.mean_abs_m) : std::nullopt;
    t["tracking.from_start_max_abs_m"] =
        f.samples ? std::optional<double>(f.max_abs_m) : std::nullopt;
    t["tracking.stable_distance_m"] = r.tracking->stable_distance_m;
    t["tracking.steady_state_mean_abs_m"] = r.tracking->steady_state_mean_abs_m;
  }
  AddPassToPassMetrics(r.pass_to_pass, t);
  AddRtkRoverMetrics(r.rtk_rover, t);
  if (r.row_following && r.row_following->samples > 0) {
    t["max_lateral_deviation_m"] = r.row_following->max_lateral_deviation_m;
    t["max_heading_deviation_deg"] = r.row_following->max_heading_deviation_deg;
  }
  if (r.closed_loop) {
    t["closed_loop.missing_commands"] = static_cast<double>(r.closed_loop->missing_commands);
    t["closed_loop.watchdog_trips"] = static_cast<double>(r.closed_loop->watchdog_trips);
    t["closed_loop.final_speed_mps"] = r.closed_loop->final_speed_mps;
    t["closed_loop.distance_after_last_command_m"] = r.closed_loop->distance_after_last_command_m;
    t["closed_loop.distance_after_watchdog_m"] = r.closed_loop->distance_after_watchdog_m;
    t["closed_loop.command_bytes_lost"] = static_cast<double>(r.closed_loop->command_bytes_lost);
    AddSteeringEcuMetrics(r.closed_loop->steering_ecu, t);
    AddClosedLoopFaultsMetrics(r.closed_loop->faults, r.tracking_faults, t);
  }
  t["output_rate_hz"] =
      r.metrics.samples >= 2 ? std::optional<double>(r.output_rate_hz) : std::nullopt;
  t["solutions_missing_fraction"] =
      r.metrics.samples >= 2 ? std::optional<double>(r.timing.missing_fraction) : std::nullopt;
  t["latency_p99_ms"] = r.latency ? std::optional<double>(r.latency->p99_ms) : std::nullopt;
  t["jitter_p99_ms"] = r.timing.jitter_p99_ms;
  std::optional<double> worst, reconv;
  std::optional<Eigen::Vector3d> worst_enu;
  bool never_reconverged = false;
  for (const auto& o : r.outages) {
    if (o.samples > 0) worst = std::max(worst.value_or(0.0), o.max_horizontal_error_m);
    if (o.samples > 0)
      worst_enu = worst_enu.value_or(Eigen::Vector3d::Zero()).cwiseMax(o.max_abs_error_enu_m);
    if (o.reconvergence_time_s)
      reconv = std::max(reconv.value_or(0.0), *o.reconvergence_time_s);
    else
      never_reconverged = true;
  }
  t["outage_max_horizontal_error_m"] = worst;
  const auto axis = [&](int i) {
    return worst_enu ? std::optional<double>((*worst_enu)[i]) : std::nullopt;
  };
  t["outage_max_east_error_m"] = axis(0);
  t["outage_max_north_error_m"] = axis(1);
  t["outage_max_up_error_m"] = axis(2);
  t["outage_max_enu_error_m"] =
      worst_enu ? std::optional<double>(worst_enu->maxCoeff()) : std::nullopt;
  t["reconvergence_time_s"] = never_reconverged ? std::nullopt : reconv;
  AddFaultMetrics(t, r.fault_injections, r.estimator_health);
  return t;
}

std::vector<CriterionResult> EvaluateCriteria(const std::vector<Criterion>& criteria,
                                              const MetricTable& metrics,
                                              const MetricTable& baselines) {
  const auto lookup = [](const MetricTable& t, const std::string& k) {
    const auto it = t.find(k);
    return it == t.end() ? std::nullopt : it->second;
  };
  std::vector<CriterionResult> out;
  for (const Criterion& c : criteria) {
    CriterionResult r;
    r.name = c.name;
    r.default_key = c.default_key;
    r.value = lookup(metrics, c.metric);
    if (c.max) {
      r.threshold = *c.max;
      r.pass = r.value && *r.value <= r.threshold;
    } else if (c.min) {
      r.threshold = *c.min;
      r.pass = r.value && *r.value >= r.threshold;
    } else {
      const auto base = lookup(baselines, c.metric);
      r.threshold = base ? *base * *c.max_ratio_to_baseline : 0.0;
      if (!base) r.value.reset();
      r.pass = r.value && *r.value <= r.threshold;
    }
    out.push_back(r);
  }
  return out;
}

std::vector<CriterionResult> EvaluateCriteria(const std::vector<Criterion>& criteria,
                                              const AccuracyMetrics& metrics,
                                              const AccuracyMetrics& baselines) {
  return EvaluateCriteria(criteria, AccuracyTable(metrics), AccuracyTable(baselines));
}

namespace {

nlohmann::json XteJson(const XteStats& x) {
  if (x.samples == 0) return {{"samples", 0}};
  return {{"samples", x.samples},
          {"cross_track_mean_abs_m", x.mean_abs_m},
          {"cross_track_rmse_m", x.rmse_m},
          {"cross_track_p95_abs_m", x.p95_abs_m},
          {"cross_track_max_abs_m", x.max_abs_m},
          {"heading_error_rms_deg", x.heading_rmse_deg}};
}

nlohmann::json TrackingJson(const TrackingMetrics& m) {
  nlohmann::json j = XteJson(m.all);
  j["initial_cross_track_m"] = m.initial_cross_track_m;
  j["settle_band_m"] = m.settle_band_m;
  j["settling_distance_m"] = OptionalJson(m.settling_distance_m);
  j["settling_time_s"] = OptionalJson(m.settling_time_s);
  j["distance_travelled_m"] = m.distance_travelled_m;
  j["from_start"] = XteJson(m.from_start);
  j["stable_distance_m"] = OptionalJson(m.stable_distance_m);
  j["steady_state_mean_abs_m"] = OptionalJson(m.steady_state_mean_abs_m);
  j["straight"] = XteJson(m.straight);
  j["turns"] = XteJson(m.turns);
  j["segments"] = nlohmann::json::array();
  for (const SegmentTracking& s : m.segments) {
    nlohmann::json e = XteJson(s.stats);
    e["index"] = s.index;
    e["kind"] = s.kind;
    e["start_s_m"] = s.start_s_m;
    e["end_s_m"] = s.end_s_m;
    j["segments"].push_back(e);
  }
  return j;
}

nlohmann::json ClosedLoopJson(const ClosedLoopReport& c) {
  nlohmann::json j = {
      {"controller_command", c.controller_command},
      {"controller_exit", c.controller_exit},
      {"control_ticks", c.control_ticks},
      {"missing_commands", c.missing_commands},
      {"first_missing_s", OptionalJson(c.first_missing_s)},
      {"motor_commands", c.motor_commands},
      {"saturated_commands", c.saturated_commands},
      {"invalid_lines", c.invalid_lines},
      {"command_bytes_lost", c.command_bytes_lost},
      {"last_command_s", OptionalJson(c.last_command_s)},
      {"watchdog_trips", c.watchdog_trips},
      {"answered_ticks_without_turn", c.answered_ticks_without_turn},
      {"watchdog_trip_s", OptionalJson(c.watchdog_trip_s)},
      {"distance_after_last_command_m", OptionalJson(c.distance_after_last_command_m)},
      {"distance_after_watchdog_m", OptionalJson(c.distance_after_watchdog_m)},
      {"final_speed_mps", c.final_speed_mps},
      {"stopped", c.stopped},
      {"stepping", c.stepping}};
  if (c.stepping == "lockstep")
    j["lockstep_pace"] = {{"actions", c.paced_actions},
                          {"late_actions", c.late_actions},
                          {"max_late_ms", c.max_late_ms}};
  AddClosedLoopFaultsJson(c.faults, j);
  return j;
}

nlohmann::json EstimatorJson(const RunReport& r) {
  return {{"command", r.estimator_command},
          {"output", r.estimator_output},
          {"exit", r.estimator_exit},
          {"pid", r.estimator_pid},
          {"solutions_outside_run", r.solutions_outside_run}};
}

nlohmann::json MetricsJson(const RunReport& r) {
  nlohmann::json m = AccuracyJson(r.metrics);
  m["output_rate_hz"] = r.output_rate_hz;
  m["solutions_missing_fraction"] = r.timing.missing_fraction;
  m["nees_mean"] = OptionalJson(r.metrics.nees_mean);
  m["nees_horizontal_mean"] = OptionalJson(r.metrics.nees_horizontal_mean);
  m["nees_vertical_mean"] = OptionalJson(r.metrics.nees_vertical_mean);
  if (r.timing.jitter_p99_ms) {
    m["jitter_ms"] = {{"p50", *r.timing.jitter_p50_ms},
                      {"p99", *r.timing.jitter_p99_ms},
                      {"max", *r.timing.jitter_max_ms}};
  } else {
    m["jitter_ms"] = nullptr;
  }
  if (r.latency) {
    m["latency_ms"] = {
        {"p50", r.latency->p50_ms}, {"p99", r.latency->p99_ms}, {"max", r.latency->max_ms}};
  } else {
    m["latency_ms"] = nullptr;  // measured in real-time mode only
  }
  m["outages"] = OutagesJson(r.outages);
  return m;
}

nlohmann::json CriteriaJson(const RunReport& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& c : r.criteria) {
    out.push_back({{"name", c.name},
                   {"threshold", c.threshold},
                   {"value", OptionalJson(c.value)},
                   {"pass", c.pass}});
    if (!c.default_key.empty()) out.back()["default"] = c.default_key;
  }
  return out;
}

nlohmann::json DefaultCriteriaJson(const RunReport& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& d : r.default_criteria) {
    out.push_back({{"key", d.key},
                   {"metric", d.metric},
                   {"status", d.status},
                   {"detail", d.detail},
                   {"bound", OptionalJson(d.bound)}});
  }
  return out;
}

}  // namespace

void WriteReportJson(const RunReport& r, const std::string& path) {
  nlohmann::json j;
  j["scenario"] = r.scenario;
  j["scenario_file"] = r.scenario_file;
  j["seed"] = r.seed;
  j["mode"] = r.mode;
  j["pass"] = r.pass();
  j["complete"] = r.complete;
  j["problems"] = r.problems;
  j["link_integrity"] = LinkIntegrityJson(r.link_integrity);
  if (!r.realtime_threads.empty()) j["realtime_threads"] = RealtimeThreadsJson(r.realtime_threads);
  j["metrics"] = MetricsJson(r);
  j["baselines"] = AccuracyJson(r.baselines);
  // every criterion metric by name (null when it cannot be computed), for suites and reference
  // figures
  j["metric_table"] = nlohmann::json::object();
  for (const auto& [name, value] : RunMetricTable(r)) j["metric_table"][name] = OptionalJson(value);
  j["baseline_table"] = nlohmann::json::object();
  for (const auto& [name, value] : AccuracyTable(r.baselines))
    j["baseline_table"][name] = OptionalJson(value);
  j["criteria"] = CriteriaJson(r);
  j["default_criteria"] = DefaultCriteriaJson(r);
  j["estimator"] = EstimatorJson(r);
  j["estimator_exit"] = r.estimator_exit;
  j["estimator_other_records"] = r.estimator_other_records;
  j["speed"] = r.speed;
  j["faults"] = nlohmann::json::array();
  for (const auto& [kind, when] : r.faults) j["faults"].push_back({{"kind", kind}, {"when", when}});
  j["fault_injections"] = FaultInjectionsJson(r.fault_injections);
  j["estimator_health"] = EstimatorHealthJson(r.estimator_health);
  if (!r.incomplete_reason.empty()) j["incomplete_reason"] = r.incomplete_reason;
  if (r.interrupt_signal != 0)
    j["interrupted_by"] = std::string("SIG") + sigabbrev_np(r.interrupt_signal);
  if (!r.write_failure.empty()) j["write_failure"] = r.write_failure;
  j["fault_effects"] = {{"messages_dropped", r.fault_messages_dropped},
                        {"bytes_corrupted", r.fault_bytes_corrupted}};
  j["wall_time_s"] = r.wall_time_s;
  j["sim_time_s"] = r.sim_time_s;
  j["priority"] = {{"nice_requested", r.nice_requested}, {"nice", r.nice}};
  if (!r.nice_refused.empty()) j["priority"]["refused"] = r.nice_refused;
  if (r.host_open_wait_s) j["host_open_wait_s"] = *r.host_open_wait_s;
  if (r.lockstep) {
    nlohmann::json procs = nlohmann::json::array();
    for (const auto& p : r.lockstep->processes)
      procs.push_back({{"pid", p.pid}, {"name", p.name}, {"clock", p.clock}});
    j["lockstep"] = {{"processes", procs},
                     {"turns", r.lockstep->turns},
                     {"lookahead", r.lockstep->lookahead},
                     {"thread_waits", r.lockstep->thread_waits},
                     {"descriptor_lookups", r.lockstep->descriptor_lookups},
                     {"wait_s", r.lockstep->wait_s}};
    if (!r.lockstep->fallback.empty()) j["lockstep"]["fallback"] = r.lockstep->fallback;
  }
  j["links"] = {{"gnss_bytes", r.gnss_bytes}, {"gnss_messages_dropped", r.gnss_messages_dropped}};
  if (r.can) j["can"] = CanBusJson(*r.can);
  if (r.tracking) {
    j["tracking"] = TrackingJson(*r.tracking);
    j["tracking"]["faults"] = FaultPathDeviationsJson(r.tracking_faults);
  }
  if (r.pass_to_pass) j["pass_to_pass"] = PassToPassJson(*r.pass_to_pass);
  if (r.rtk_rover) j["rtk_rover"] = RtkRoverJson(*r.rtk_rover);
  if (r.closed_loop) {
    j["closed_loop"] = ClosedLoopJson(*r.closed_loop);
    if (r.closed_loop->steering_ecu)
      j["closed_loop"]["steering_ecu"] = SteeringEcuJson(*r.closed_loop->steering_ecu);
  }
  if (r.row_following)
    j["row_following"] = {
        {"samples", r.row_following->samples},
        {"max_lateral_deviation_m", r.row_following->max_lateral_deviation_m},
        {"mean_abs_lateral_deviation_m", r.row_following->mean_abs_lateral_m},
        {"max_heading_deviation_deg", r.row_following->max_heading_deviation_deg}};
  WriteOutputFile(path, j.dump(2) + "\n");
}

void WriteJunitXml(const RunReport& r, const std::string& path) {
  std::size_t failures = r.problems.size();
  for (const auto& c : r.criteria) failures += c.pass ? 0 : 1;
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << "<testsuites>\n";
  out << "  <testsuite name=\"" << XmlEscape(r.scenario) << "\" tests=\""
      << r.criteria.size() + r.problems.size() << "\" failures=\"" << failures << "\" time=\""
      << r.wall_time_s << "\">\n";
  for (const auto& c : r.criteria) {
    out << "    <testcase classname=\"" << XmlEscape(r.scenario) << "\" name=\""
        << XmlEscape(c.name) << "\">";
    if (!c.pass) {
      char msg[256];
      if (c.value)
        std::snprintf(msg, sizeof msg, "value %.6g fails the threshold %.6g", *c.value,
                      c.threshold);
      else
        std::snprintf(msg, sizeof msg,
                      "metric could not be computed (no estimates, or not measured in this mode)");
      out << "<failure message=\"" << XmlEscape(msg) << "\"/>";
    }
    out << "</testcase>\n";
  }
  for (const auto& p : r.problems) {
    out << "    <testcase classname=\"" << XmlEscape(r.scenario)
        << "\" name=\"run\"><failure message=\"" << XmlEscape(p) << "\"/></testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
  WriteOutputFile(path, out.str());
}

void AppendErrorsCsvHeader(std::string& text) {
  text +=
      "t_s,truth_e_m,truth_n_m,truth_u_m,est_e_m,est_n_m,est_u_m,err_e_m,err_n_m,err_u_m,err_h_"
      "m\n";
}

void AppendErrorsCsvRow(std::string& text, const ErrorSample& e) {
  AppendFixedRow(text, 6, ToSeconds(e.t), e.truth_enu_m.x(), e.truth_enu_m.y(), e.truth_enu_m.z(),
                 e.est_enu_m.x(), e.est_enu_m.y(), e.est_enu_m.z(), e.err_enu_m.x(),
                 e.err_enu_m.y(), e.err_enu_m.z(), e.horizontal());
  text.push_back('\n');
}

void WriteErrorsCsv(const std::vector<ErrorSample>& errors, const std::string& path) {
  OutputFile out(path);
  std::string& text = out.text();
  AppendErrorsCsvHeader(text);
  for (const auto& e : errors) {
    AppendErrorsCsvRow(text, e);
    out.Pass();
  }
  out.Commit();
}

}  // namespace hil::harness

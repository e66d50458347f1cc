#include "hil/harness/report.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace hil::harness {
namespace {

std::optional<double> MetricValue(const AccuracyMetrics& m, const std::string& name) {
  if (m.samples == 0) return std::nullopt;
  if (name == "horizontal_rmse_m") return m.horizontal_rmse_m;
  if (name == "cep50_m") return m.cep50_m;
  if (name == "cep95_m") return m.cep95_m;
  if (name == "max_horizontal_error_m") return m.max_horizontal_error_m;
  if (name == "vertical_rmse_m") return m.vertical_rmse_m;
  if (name == "velocity_rmse_mps") return m.velocity_rmse_mps;
  if (name == "heading_rmse_deg") return m.heading_rmse_deg;
  return std::nullopt;
}

nlohmann::json OptionalJson(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json AccuracyJson(const AccuracyMetrics& m) {
  nlohmann::json j;
  j["samples"] = m.samples;
  j["horizontal_rmse_m"] = m.samples ? nlohmann::json(m.horizontal_rmse_m) : nlohmann::json(nullptr);
  j["cep50_m"] = m.samples ? nlohmann::json(m.cep50_m) : nlohmann::json(nullptr);
  j["cep95_m"] = m.samples ? nlohmann::json(m.cep95_m) : nlohmann::json(nullptr);
  j["max_horizontal_error_m"] = m.samples ? nlohmann::json(m.max_horizontal_error_m) : nlohmann::json(nullptr);
  j["vertical_rmse_m"] = m.samples ? nlohmann::json(m.vertical_rmse_m) : nlohmann::json(nullptr);
  j["velocity_rmse_mps"] = OptionalJson(m.velocity_rmse_mps);
  j["heading_rmse_deg"] = OptionalJson(m.heading_rmse_deg);
  return j;
}

std::string XmlEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '&': o += "&amp;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::ofstream OpenOut(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  return out;
}

}  // namespace

bool RunReport::pass() const {
  if (!complete || !problems.empty()) return false;
  for (const auto& c : criteria) {
    if (!c.pass) return false;
  }
  return true;
}

std::vector<CriterionResult> EvaluateCriteria(const std::vector<Criterion>& criteria, const AccuracyMetrics& metrics,
                                              const AccuracyMetrics& baselines) {
  std::vector<CriterionResult> out;
  for (const Criterion& c : criteria) {
    CriterionResult r;
    r.name = c.name;
    r.value = MetricValue(metrics, c.metric);
    if (c.max) {
      r.threshold = *c.max;
    } else {
      const auto base = MetricValue(baselines, c.metric);
      r.threshold = base ? *base * *c.max_ratio_to_baseline : 0.0;
      if (!base) r.value.reset();
    }
    r.pass = r.value && *r.value <= r.threshold;
    out.push_back(r);
  }
  return out;
}

void WriteReportJson(const RunReport& r, const std::string& path) {
  nlohmann::json j;
  j["scenario"] = r.scenario;
  j["scenario_file"] = r.scenario_file;
  j["seed"] = r.seed;
  j["mode"] = r.mode;
  j["pass"] = r.pass();
  j["complete"] = r.complete;
  j["problems"] = r.problems;
  nlohmann::json m = AccuracyJson(r.metrics);
  m["output_rate_hz"] = r.output_rate_hz;
  if (r.latency) {
    m["latency_ms"] = {{"p50", r.latency->p50_ms}, {"p99", r.latency->p99_ms}, {"max", r.latency->max_ms}};
  } else {
    m["latency_ms"] = nullptr;  // measured in real-time mode only
  }
  m["outages"] = nlohmann::json::array();
  j["metrics"] = m;
  j["baselines"] = AccuracyJson(r.baselines);
  j["criteria"] = nlohmann::json::array();
  for (const auto& c : r.criteria) {
    j["criteria"].push_back({{"name", c.name}, {"threshold", c.threshold}, {"value", OptionalJson(c.value)}, {"pass", c.pass}});
  }
  j["estimator_exit"] = r.estimator_exit;
  j["wall_time_s"] = r.wall_time_s;
  j["sim_time_s"] = r.sim_time_s;
  j["links"] = {{"gnss_bytes", r.gnss_bytes}, {"gnss_messages_dropped", r.gnss_messages_dropped}};
  auto out = OpenOut(path);
  out << j.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
}

void WriteJunitXml(const RunReport& r, const std::string& path) {
  std::size_t failures = r.problems.size();
  for (const auto& c : r.criteria) failures += c.pass ? 0 : 1;
  auto out = OpenOut(path);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out << "<testsuites>\n";
  out << "  <testsuite name=\"" << XmlEscape(r.scenario) << "\" tests=\"" << r.criteria.size() + r.problems.size()
      << "\" failures=\"" << failures << "\" time=\"" << r.wall_time_s << "\">\n";
  for (const auto& c : r.criteria) {
    out << "    <testcase classname=\"" << XmlEscape(r.scenario) << "\" name=\"" << XmlEscape(c.name) << "\">";
    if (!c.pass) {
      char msg[256];
      if (c.value) std::snprintf(msg, sizeof msg, "value %.6g exceeds threshold %.6g", *c.value, c.threshold);
      else std::snprintf(msg, sizeof msg, "metric could not be computed (no estimates)");
      out << "<failure message=\"" << XmlEscape(msg) << "\"/>";
    }
    out << "</testcase>\n";
  }
  for (const auto& p : r.problems) {
    out << "    <testcase classname=\"" << XmlEscape(r.scenario) << "\" name=\"run\"><failure message=\""
        << XmlEscape(p) << "\"/></testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
  if (!out) throw std::runtime_error("cannot write " + path);
}

void WriteErrorsCsv(const std::vector<ErrorSample>& errors, const std::string& path) {
  auto out = OpenOut(path);
  out << "t_s,truth_e_m,truth_n_m,truth_u_m,est_e_m,est_n_m,est_u_m,err_e_m,err_n_m,err_u_m,err_h_m\n";
  char line[512];
  for (const auto& e : errors) {
    std::snprintf(line, sizeof line, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", ToSeconds(e.t),
                  e.truth_enu_m.x(), e.truth_enu_m.y(), e.truth_enu_m.z(), e.est_enu_m.x(), e.est_enu_m.y(),
                  e.est_enu_m.z(), e.err_enu_m.x(), e.err_enu_m.y(), e.err_enu_m.z(), e.horizontal());
    out << line;
  }
}

}  // namespace hil::harness

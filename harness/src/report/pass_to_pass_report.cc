#include "hil/harness/report/pass_to_pass_report.h"

#include <cstdio>

#include <nlohmann/json.hpp>

namespace hil::harness {
namespace {

nlohmann::json StatsJson(const PassErrorStats& s) {
  if (s.samples == 0)
    return {{"samples", 0},
            {"mean_m", nullptr},
            {"mean_abs_m", nullptr},
            {"p95_abs_m", nullptr},
            {"max_abs_m", nullptr}};
  return {{"samples", s.samples},
          {"mean_m", s.mean_m},
          {"mean_abs_m", s.mean_abs_m},
          {"p95_abs_m", s.p95_abs_m},
          {"max_abs_m", s.max_abs_m}};
}

void AddStats(const std::string& prefix, const PassErrorStats& s,
              std::map<std::string, std::optional<double>>& t) {
  const auto v = [&s](double x) { return s.samples ? std::optional<double>(x) : std::nullopt; };
  t[prefix + ".mean_m"] = v(s.mean_m);
  t[prefix + ".mean_abs_m"] = v(s.mean_abs_m);
  t[prefix + ".p95_abs_m"] = v(s.p95_abs_m);
  t[prefix + ".max_abs_m"] = v(s.max_abs_m);
}

std::string PassErrorRow(const char* name, const PassErrorStats& s) {
  char buf[256];
  if (s.samples == 0) {
    std::snprintf(buf, sizeof buf,
                  "<tr><td>%s</td><td>0</td><td>n/a</td><td>n/a</td><td>n/a</td>"
                  "<td>n/a</td></tr>\n",
                  name);
  } else {
    std::snprintf(buf, sizeof buf,
                  "<tr><td>%s</td><td>%zu</td><td>%.4f</td><td>%.4f</td><td>%.4f</td><td>%.4f</td>"
                  "</tr>\n",
                  name, s.samples, s.mean_m, s.mean_abs_m, s.p95_abs_m, s.max_abs_m);
  }
  return buf;
}

}  // namespace

nlohmann::json PassToPassJson(const PassToPassMetrics& m) {
  nlohmann::json j;
  j["window_s"] = m.config.window_s;
  j["margin_m"] = m.config.margin_m;
  j["max_angle_deg"] = m.config.max_angle_deg;
  j["window_start_s"] = m.window_start_s;
  j["window_end_s"] = m.window_end_s;
  j["passes"] = m.passes;
  j["nearest_point"] = StatsJson(m.nearest_point);
  j["interpolated"] = StatsJson(m.interpolated);
  j["method_difference_mean_m"] =
      m.interpolated.samples ? nlohmann::json(m.method_difference_mean_m) : nlohmann::json(nullptr);
  j["method_difference_max_m"] =
      m.interpolated.samples ? nlohmann::json(m.method_difference_max_m) : nlohmann::json(nullptr);
  j["absolute"] = StatsJson(m.absolute);
  j["pairs"] = nlohmann::json::array();
  for (const PassPair& p : m.pairs) {
    j["pairs"].push_back({{"from_segment", p.from_segment},
                          {"to_segment", p.to_segment},
                          {"spacing_m", p.spacing_m},
                          {"nearest_point", StatsJson(p.nearest_point)},
                          {"interpolated", StatsJson(p.interpolated)}});
  }
  return j;
}

void AddPassToPassMetrics(const std::optional<PassToPassMetrics>& m,
                          std::map<std::string, std::optional<double>>& table) {
  if (!m) return;
  AddStats("pass_to_pass.nearest_point", m->nearest_point, table);
  AddStats("pass_to_pass.interpolated", m->interpolated, table);
  AddStats("pass_to_pass.absolute", m->absolute, table);
  table["pass_to_pass.method_difference_max_m"] =
      m->interpolated.samples ? std::optional<double>(m->method_difference_max_m) : std::nullopt;
  table["pass_to_pass.pairs"] = static_cast<double>(m->pairs.size());
}

void AppendPassToPassHtml(std::string& h, const PassToPassMetrics& m) {
  char buf[512];
  h += "<h2>Pass-to-pass (ISO 12188-2 style)</h2>\n";
  std::snprintf(buf, sizeof buf,
                "<p>%zu passes and %zu adjacent pairs from %.1f s to %.1f s (window %.0f s, %.1f m "
                "left out at each end of a pass). Error: distance to the previous pass's driven "
                "track minus the planned spacing (+ gap, − overlap), metres.</p>\n",
                m.passes, m.pairs.size(), m.window_start_s, m.window_end_s, m.config.window_s,
                m.config.margin_m);
  h += buf;
  h += "<table><tr><th>method</th><th>samples</th><th>mean</th><th>mean |e|</th><th>p95 |e|</th>"
       "<th>max |e|</th></tr>\n";
  h += PassErrorRow("nearest point", m.nearest_point);
  h += PassErrorRow("interpolated", m.interpolated);
  h += PassErrorRow("absolute (against the planned rows)", m.absolute);
  h += "</table>\n";
  if (m.interpolated.samples) {
    std::snprintf(buf, sizeof buf,
                  "<p>|nearest point − interpolated|: mean %.4f m, max %.4f m.</p>\n",
                  m.method_difference_mean_m, m.method_difference_max_m);
    h += buf;
  }
  if (m.pairs.empty()) return;
  h += "<table><tr><th>pair (segments)</th><th>spacing</th><th>samples</th><th>interpolated mean "
       "|e| / p95 / max</th><th>nearest point mean |e| / p95 / max</th></tr>\n";
  for (const PassPair& p : m.pairs) {
    std::snprintf(buf, sizeof buf,
                  "<tr><td>%d → %d</td><td>%.2f m</td><td>%zu</td><td>%.4f / %.4f / %.4f</td>"
                  "<td>%.4f / %.4f / %.4f</td></tr>\n",
                  p.from_segment, p.to_segment, p.spacing_m, p.interpolated.samples,
                  p.interpolated.mean_abs_m, p.interpolated.p95_abs_m, p.interpolated.max_abs_m,
                  p.nearest_point.mean_abs_m, p.nearest_point.p95_abs_m, p.nearest_point.max_abs_m);
    h += buf;
  }
  h += "</table>\n";
}

}  // namespace hil::harness

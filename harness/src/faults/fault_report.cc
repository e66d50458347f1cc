#include "hil/harness/faults/fault_report.h"

#include <algorithm>

#include <nlohmann/json.hpp>

namespace hil::harness {

const std::vector<std::string> kNavdFlags{"gnss_outage",   "gnss_link_errors", "imu_link_errors",
                                          "gnss_rejected", "imu_gap",          "mcu_reset"};

void EstimatorHealth::AddLine(const std::string& line) {
  if (line.find("\"health\"") == std::string::npos) return;
  AddJson(nlohmann::json::parse(line, nullptr, false));
}

void EstimatorHealth::AddJson(const nlohmann::json& j) {
  if (j.is_discarded() || !j.is_object() || !j.contains("health") || !j["health"].is_object())
    return;
  const bool first = !present;
  present = true;
  for (const auto& [key, value] : j["health"].items()) {
    if (value.is_number()) counters[key] = value.get<double>();
    if (value.is_number() && first) first_counters[key] = value.get<double>();
    if (key == "flags" && value.is_array()) {
      for (const auto& f : value) {
        if (f.is_string()) flags_seen.insert(f.get<std::string>());
      }
    }
  }
}

void EstimatorHealth::AddScanned(const JsonSolutionLine& line) {
  if (!line.health) return;
  const bool first = !present;
  present = true;
  const std::vector<std::string>& keys = *line.health_keys;
  for (std::size_t i = 0; i < line.health_values.size(); ++i) {
    if (line.health_values[i]) counters[keys[i]] = *line.health_values[i];
    if (line.health_values[i] && first) first_counters[keys[i]] = *line.health_values[i];
  }
  flags_seen.insert(line.health_flags.begin(), line.health_flags.end());
}

void ComputeRecoveryTimes(std::vector<FaultInjection>& faults,
                          const std::vector<ErrorSample>& errors, double threshold_m) {
  constexpr double kStayS = 2.0;
  for (FaultInjection& f : faults) {
    f.recovery_time_s.reset();
    const double end = std::max(f.end_s, f.start_s);
    std::vector<const ErrorSample*> after;
    for (const ErrorSample& e : errors) {
      if (ToSeconds(e.t) >= end) after.push_back(&e);
    }
    // the first run of good solutions lasting 2 s (or lasting to the end of the run)
    for (std::size_t i = 0; i < after.size(); ++i) {
      if (after[i]->horizontal() >= threshold_m) continue;
      std::size_t j = i;
      while (j + 1 < after.size() && after[j + 1]->horizontal() < threshold_m) ++j;
      const double t0 = ToSeconds(after[i]->t);
      if (ToSeconds(after[j]->t) - t0 >= kStayS || j + 1 == after.size()) {
        f.recovery_time_s = t0 - end;
        break;
      }
      i = j;
    }
  }
}

void AddFaultMetrics(std::map<std::string, std::optional<double>>& table,
                     const std::vector<FaultInjection>& faults, const EstimatorHealth& health) {
  std::optional<double> worst, fewest;
  bool never = false;
  for (const FaultInjection& f : faults) {
    if (f.recovery_time_s)
      worst = std::max(worst.value_or(0.0), *f.recovery_time_s);
    else
      never = true;
    fewest = std::min(fewest.value_or(static_cast<double>(f.count)), static_cast<double>(f.count));
  }
  table["fault_recovery_time_s"] = never || faults.empty() ? std::nullopt : worst;
  table["fault_injections_min"] = fewest;
  if (!health.present) return;
  for (const auto& [k, v] : health.counters) table["navd." + k] = v;
  for (const std::string& f : kNavdFlags)
    table["navd.flag." + f] = health.flags_seen.count(f) ? 1.0 : 0.0;
  for (const std::string& f : health.flags_seen) table["navd.flag." + f] = 1.0;
}

nlohmann::json FaultInjectionsJson(const std::vector<FaultInjection>& faults) {
  nlohmann::json a = nlohmann::json::array();
  for (const FaultInjection& f : faults) {
    a.push_back({{"kind", f.kind},
                 {"link", f.link},
                 {"start_s", f.start_s},
                 {"end_s", f.end_s},
                 {"unit", f.unit},
                 {"count", f.count},
                 {"times_s", f.times_s},
                 {"recovery_time_s", f.recovery_time_s ? nlohmann::json(*f.recovery_time_s)
                                                       : nlohmann::json(nullptr)}});
  }
  return a;
}

nlohmann::json EstimatorHealthJson(const EstimatorHealth& h) {
  return {{"present", h.present}, {"counters", h.counters}, {"flags_seen", h.flags_seen}};
}

}  // namespace hil::harness

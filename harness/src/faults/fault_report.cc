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

RecoveryTimeAccumulator::RecoveryTimeAccumulator(const std::vector<FaultInjection>& faults,
                                                 double threshold_m)
    : threshold_m_(threshold_m) {
  for (const FaultInjection& f : faults) faults_.push_back({std::max(f.end_s, f.start_s), {}, {}});
}

void RecoveryTimeAccumulator::Add(const ErrorSample& e) {
  constexpr double kStayS = 2.0;
  const double t = ToSeconds(e.t);
  const bool good = e.horizontal() < threshold_m_;
  for (Fault& f : faults_) {
    if (f.recovery_s || t < f.end_s) continue;
    if (!good) {
      f.run_start_s.reset();
      continue;
    }
    if (!f.run_start_s) f.run_start_s = t;
    // the first run of good solutions lasting 2 s
    if (t - *f.run_start_s >= kStayS) f.recovery_s = *f.run_start_s - f.end_s;
  }
}

void RecoveryTimeAccumulator::Apply(std::vector<FaultInjection>& faults) const {
  for (std::size_t i = 0; i < faults.size() && i < faults_.size(); ++i) {
    const Fault& f = faults_[i];
    faults[i].recovery_time_s = f.recovery_s;
    // ... or lasting to the end of the run
    if (!f.recovery_s && f.run_start_s) faults[i].recovery_time_s = *f.run_start_s - f.end_s;
  }
}

void ComputeRecoveryTimes(std::vector<FaultInjection>& faults,
                          const std::vector<ErrorSample>& errors, double threshold_m) {
  RecoveryTimeAccumulator a(faults, threshold_m);
  for (const ErrorSample& e : errors) a.Add(e);
  a.Apply(faults);
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

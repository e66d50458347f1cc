#include "hil/harness/report/closed_loop_faults_report.h"

#include <algorithm>

namespace hil::harness {
namespace {

nlohmann::json Opt(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

void AddClosedLoopFaultsJson(const ClosedLoopFaultsReport& r, nlohmann::json& closed_loop) {
  closed_loop["saturated_time_s"] = r.saturated_time_s;
  closed_loop["delayed_commands"] = r.delayed_commands;
  closed_loop["added_latency_mean_s"] = Opt(r.added_latency_mean_s);
  closed_loop["added_latency_max_s"] = Opt(r.added_latency_max_s);
  closed_loop["stuck_time_s"] = r.stuck_time_s;
  closed_loop["commands_not_followed"] = r.commands_not_followed;
}

nlohmann::json FaultPathDeviationsJson(const std::vector<FaultPathDeviation>& d) {
  nlohmann::json a = nlohmann::json::array();
  for (const FaultPathDeviation& f : d) {
    a.push_back({{"kind", f.kind},
                 {"start_s", f.start_s},
                 {"end_s", f.end_s},
                 {"window_s", f.window_s},
                 {"samples", f.samples},
                 {"cross_track_at_start_m", Opt(f.cross_track_at_start_m)},
                 {"max_deviation_m", Opt(f.max_deviation_m)},
                 {"max_deviation_s", Opt(f.max_deviation_s)},
                 {"cross_track_at_max_m", Opt(f.cross_track_at_max_m)},
                 {"max_abs_cross_track_m", Opt(f.max_abs_cross_track_m)}});
  }
  return a;
}

void AddClosedLoopFaultsMetrics(const ClosedLoopFaultsReport& r,
                                const std::vector<FaultPathDeviation>& d,
                                std::map<std::string, std::optional<double>>& table) {
  table["closed_loop.saturated_time_s"] = r.saturated_time_s;
  table["closed_loop.stuck_time_s"] = r.stuck_time_s;
  table["closed_loop.delayed_commands"] = static_cast<double>(r.delayed_commands);
  table["closed_loop.added_latency_max_s"] = r.added_latency_max_s;
  std::optional<double> worst;
  for (const FaultPathDeviation& f : d) {
    if (f.max_deviation_m) worst = std::max(worst.value_or(0.0), *f.max_deviation_m);
  }
  table["tracking.fault_deviation_max_m"] = worst;
}

}  // namespace hil::harness

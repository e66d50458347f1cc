#pragma once
/// @file
/// Closed loop: what the actuator faults did (report.json `closed_loop`: saturated_time_s,
/// delayed_commands, added_latency_mean_s / _max_s, stuck_time_s, commands_not_followed) and
/// what every fault did to the path tracking (`tracking.faults`, fault_path_deviation.h).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hil/harness/eval/fault_path_deviation.h"

namespace hil::harness {

struct ClosedLoopFaultsReport {
  /// Time a wheel's target was beyond the drive's speed limit (the nominal one or a
  /// saturation fault's), clamped to it.
  double saturated_time_s = 0;
  std::uint64_t delayed_commands = 0;  ///< commands a command_latency fault delayed
  std::optional<double> added_latency_mean_s, added_latency_max_s;
  double stuck_time_s = 0;                  ///< time an actuator_stuck fault held the output
  std::uint64_t commands_not_followed = 0;  ///< commands that arrived while it held
};

/// Adds the figures to the `closed_loop` object.
void AddClosedLoopFaultsJson(const ClosedLoopFaultsReport& r, nlohmann::json& closed_loop);
/// `tracking.faults`: one object per fault of the scenario.
nlohmann::json FaultPathDeviationsJson(const std::vector<FaultPathDeviation>& d);
/// The criteria's names: closed_loop.saturated_time_s, closed_loop.stuck_time_s,
/// closed_loop.delayed_commands, closed_loop.added_latency_max_s and
/// tracking.fault_deviation_max_m (the largest max_deviation_m of all faults).
void AddClosedLoopFaultsMetrics(const ClosedLoopFaultsReport& r,
                                const std::vector<FaultPathDeviation>& d,
                                std::map<std::string, std::optional<double>>& table);

}  // namespace hil::harness

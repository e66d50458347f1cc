#pragma once
/// @file
/// A criterion across runs: a campaign file's `criteria` item and a scenario's
/// `statistical.criteria` item (both read here, so the scenario and the campaign share one
/// reader). Read strictly: every error is a ScenarioError naming the file, the line and the field.

#include <optional>
#include <string>

namespace hil::harness {

class YamlReader;

/// A criterion across the runs of each group (one scenario at one sweep point, over its seeds).
/// kind "stat": `stat` (mean, p50, p95, max, min) of `metric` ≤ max or ≥ min. kind
/// "pass_fraction": the fraction of the group's runs that pass their scenario's own criteria ≥ min.
struct CampaignCriterion {
  std::string name;
  std::string kind = "stat";
  std::string metric;  ///< a criterion metric (kCriterionMetrics, navd.*); kind "stat" only
  std::string stat = "p95";
  std::optional<double> max, min;
  std::string scenarios;  ///< a glob on the scenario's name; empty: every group
};

/// One criterion across runs (a campaign file's `criteria` item, a scenario's
/// `statistical.criteria` item): {metric, stat, max | min, name, scenarios} or {pass_fraction,
/// name, scenarios}.
/// @throws ScenarioError.
CampaignCriterion ReadCampaignCriterion(const YamlReader& y);

/// The statistics a campaign criterion may take, and the report gives per metric.
inline constexpr const char* kCampaignStats[] = {"mean", "p50", "p95", "max", "min"};

}  // namespace hil::harness

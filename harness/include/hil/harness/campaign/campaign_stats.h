#pragma once
/// @file
/// Statistics across a campaign's runs: per group (a scenario at a sweep point, over its seeds)
/// the n, mean, p50, p95, min and max of every metric, and the campaign's criteria on them.
/// Percentiles interpolate linearly between order statistics (the sorted values x_0 … x_{n-1}:
/// p-th percentile at rank h = (n - 1) p, x_⌊h⌋ + (h - ⌊h⌋)(x_⌊h⌋+1 - x_⌊h⌋); numpy's default).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hil/harness/campaign/campaign_plan.h"

namespace hil::harness {

/// The p-quantile (0 ≤ p ≤ 1) of sorted values (at least one).
double SortedQuantile(const std::vector<double>& sorted, double p);

/// {"n", "mean", "p50", "p95", "min", "max"} of the numbers among `values` (nulls when none).
nlohmann::json MetricStats(const std::vector<nlohmann::json>& values);

/// The statistic `stat` (kCampaignStats) of a MetricStats object (null when n = 0).
nlohmann::json StatOf(const nlohmann::json& stats, const std::string& stat);

/// The campaign's criteria evaluated on each group they apply to: [{name, kind, metric, stat,
/// relation, threshold, pass, groups: [{group, scenario, value, n, pass, failing_runs}]}].
/// `groups` are the summary's group entries (id, scenario, metrics, runs); `runs` the run records
/// in plan order. A failing run is one whose own value breaks the bound (or has none), or, for a
/// pass fraction, one that failed its scenario's criteria.
nlohmann::json EvaluateCampaignCriteria(const CampaignPlan& plan, const nlohmann::json& groups,
                                        const nlohmann::json& runs);

}  // namespace hil::harness

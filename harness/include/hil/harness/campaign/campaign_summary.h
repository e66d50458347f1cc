#pragma once
/// @file
/// A campaign's summary (summary.json) from its run records: the runs, the suite's side-by-side
/// entries per group (suite_report.h: the papers' figures, criteria per seed, outages), the
/// statistics of every metric per group (campaign_stats.h) and the campaign's criteria. Nothing in
/// it depends on who ran the runs, where or when: merging N shards gives the bytes `--local` gives.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hil/harness/campaign/campaign_folder.h"

namespace hil::harness {

/// `runs`: the `run` part of each present record, in plan order; `missing`: the ids without one.
nlohmann::json SummariseCampaign(const CampaignFolder& folder, const nlohmann::json& runs,
                                 const std::vector<std::string>& missing);

/// The metrics the report tables and plots show: horizontal RMSE, CEP95 and the maximum error,
/// then every metric a scenario criterion or a campaign criterion names, in order of appearance.
std::vector<std::string> ReportMetrics(const nlohmann::json& summary);

}  // namespace hil::harness

#pragma once
/// @file
/// A campaign's plan: its groups (each scenario at each sweep point) and its runs (each group at
/// each seed), in a fixed order that every mode (local, a shard, a Slurm array task, the merge)
/// derives alike from the campaign's spec. Shards take the runs round robin (run k belongs to shard
/// k mod N + 1), so each shard gets a share of every scenario's seeds.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hil/harness/campaign/campaign_spec.h"

namespace hil::harness {

/// One scenario at one sweep point.
struct CampaignGroup {
  std::string id;  ///< the scenario file's stem, plus `__p<k>` for sweep point k
  std::string scenario_file;
  std::size_t point = 0;
  std::vector<ScenarioOverride> settings;  ///< the sweep point's field values
};

/// One `hil run`.
struct CampaignRun {
  std::size_t index = 0;
  std::string id;  ///< the group's id, plus `-seed<N>`: names its run folder and its record
  std::size_t group = 0;
  std::optional<std::uint64_t> seed;  ///< absent: the scenario's own
};

struct CampaignPlan {
  CampaignSpec spec;
  std::vector<CampaignGroup> groups;
  std::vector<CampaignRun> runs;
};

/// The groups and runs of a spec.
CampaignPlan PlanCampaign(const CampaignSpec& spec);

/// The spec as JSON (campaign.json's `plan`), and back (re-planned).
/// @throws std::runtime_error for a malformed object.
nlohmann::json PlanToJson(const CampaignPlan& plan);
CampaignPlan PlanFromJson(const nlohmann::json& json);

/// The runs of shard `shard` (1-based) of `shards`: indices k with k mod shards == shard - 1.
std::vector<std::size_t> ShardRuns(const CampaignPlan& plan, int shard, int shards);
/// The shard (1-based) run `index` belongs to.
int ShardOfRun(std::size_t index, int shards);

}  // namespace hil::harness

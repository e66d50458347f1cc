#pragma once
/// @file
/// A campaign folder, which every mode shares:
///
/// | path | content |
/// |---|---|
/// | `campaign.json` | the plan (campaign_plan.h), the shard count, the folder runs were started
/// from | | `records/<run id>.json` | one per finished run: its result (`run`) and its timing
/// (`timing`) | | `runs/<run id>/` | the run's own folder (`hil run --out`), with `hil.log` | |
/// `shards/shard-<i>.json` | a shard's state: started (host, pid) or finished (exit code) | |
/// `slurm/*.sbatch`, `slurm/jobs.json`, `logs/` | the Slurm array and merge jobs (campaign_slurm.h)
/// | | `summary.json`, `report.md`, `report.html`, `junit.xml`, `plots/` | the merge's outputs | |
/// `timing.json` | wall times per run and shard (not part of the byte-for-byte outputs) |
///
/// A record is written to a temporary file and renamed, so it is either complete or absent; a run
/// with a record is done, and a resubmitted shard skips it.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "hil/harness/campaign/campaign_plan.h"

namespace hil::harness {

/// What campaign.json holds.
struct CampaignFolder {
  std::string dir;
  CampaignPlan plan;
  int shards = 1;
  std::string workdir;  ///< the folder relative scenario paths are relative to
};

/// Thrown when a folder holds another campaign, or another shard count (exit code 2).
class CampaignFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Creates DIR and its campaign.json, or checks that the one there holds the same plan; `shards`
/// > 0 must then match its shard count (0: keep it; 1 for a new folder). @throws
/// CampaignFolderError.
CampaignFolder PrepareCampaignFolder(const std::string& dir, const CampaignPlan& plan, int shards);

/// Reads DIR/campaign.json. @throws CampaignFolderError when it is missing or malformed.
CampaignFolder LoadCampaignFolder(const std::string& dir);

/// Writes `text` to `path` through a temporary file in the same folder and a rename.
/// @throws std::runtime_error when it cannot.
void WriteFileAtomically(const std::string& path, const std::string& text);

std::string RecordPath(const std::string& dir, const CampaignRun& run);
/// The run's record when it is there and whole (its `run.id` is the run's).
std::optional<nlohmann::json> ReadRecord(const std::string& dir, const CampaignRun& run);

std::string ShardStatePath(const std::string& dir, int shard);

}  // namespace hil::harness

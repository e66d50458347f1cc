#pragma once
/// @file
/// `hil campaign status DIR` and `hil campaign merge DIR`: which shards are complete, running, or
/// failed/killed (by name, with the runs they lack), and the merge of the run records into
/// summary.json, report.md, report.html, junit.xml and plots/cdf_<metric>.svg (campaign_report.h),
/// plus timing.json. The merge refuses a campaign with missing runs unless `allow_partial`.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hil/harness/campaign/campaign_folder.h"

namespace hil::harness {

/// Exit codes of the campaign commands beyond 0 (pass), 1 (fail), 2 (bad input).
inline constexpr int kExitIncomplete = 3;  ///< runs are missing (a shard failed or was killed)

struct ShardProgress {
  int shard = 0;  ///< 1-based
  std::size_t runs = 0, done = 0;
  std::vector<std::string> missing;  ///< run ids without a record
  std::string state;                 ///< complete, not started, running, failed, killed
  std::string detail;                ///< host, pid, exit code, log file
};

struct CampaignProgress {
  std::size_t runs = 0, done = 0, passed = 0, failed = 0;
  std::vector<ShardProgress> shards;
  bool complete() const { return done == runs; }
};

CampaignProgress ReadProgress(const CampaignFolder& folder);
/// What `hil campaign status` prints: a line for the campaign, one per shard.
std::string ProgressText(const CampaignFolder& folder, const CampaignProgress& progress);

struct MergeOutcome {
  int exit_code = 0;  ///< 0 pass, 1 fail, 2 an invalid run, kExitIncomplete missing runs
  bool written = false;
  nlohmann::json summary;
};

/// Merges the folder's records. @throws std::runtime_error when an output cannot be written.
MergeOutcome MergeCampaign(const CampaignFolder& folder, bool allow_partial);

}  // namespace hil::harness

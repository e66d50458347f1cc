#pragma once
/// @file
/// Runs a campaign's runs as child `hil run` processes, `jobs` at a time, each into
/// DIR/runs/<id>/, and writes each one's record (campaign_folder.h) the moment it ends. Runs that
/// already have a record are skipped, so a resubmitted shard or a repeated `--local` does only
/// what is missing. A progress line (runs done/total, pass/fail, ETA) goes to stderr: rewritten in
/// place on a terminal, one line per finished run otherwise (a Slurm log).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "hil/harness/campaign/campaign_folder.h"

namespace hil::harness {

struct RunnerOptions {
  std::string hil_exe;  ///< the hil binary the runs use
  int jobs = 2;
  std::string label = "local";  ///< what the progress line calls this process ("shard 2/4")
  bool live = false;            ///< rewrite the progress line in place (stderr is a terminal)
  std::optional<int> nice;      ///< `--nice` of every run (unset: hil run's default)
};

struct RunnerResult {
  std::size_t ran = 0, skipped = 0, recorded = 0;
};

/// Runs the plan's runs at `indices` that have no record yet.
/// @throws std::runtime_error when a child cannot be started or a record cannot be written.
RunnerResult RunCampaignRuns(const CampaignFolder& folder, const std::vector<std::size_t>& indices,
                             const RunnerOptions& options);

/// A finished run's record: `run` (its result, the same bytes whoever ran it) and `timing`.
nlohmann::json MakeRunRecord(const CampaignPlan& plan, const CampaignRun& run, int exit_code,
                             const nlohmann::json& report, const std::string& log_tail,
                             double wall_s);

}  // namespace hil::harness

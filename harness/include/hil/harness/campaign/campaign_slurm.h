#pragma once
/// @file
/// `hil campaign FILE --slurm`: the campaign as a Slurm job array, one array task per shard (each
/// `hil campaign FILE --shard $SLURM_ARRAY_TASK_ID/N`), and a merge job that starts when every task
/// succeeded (`--dependency=afterok`, `--kill-on-invalid-dep=yes`). Both scripts are written into
/// DIR/slurm/ so a user can read and resubmit them (`sbatch --array=3,5 DIR/slurm/shards.sbatch`);
/// each task writes DIR/logs/shard-<i>.out. Submitting again into the same folder submits only the
/// shards that still lack runs. No scheduler of our own: sbatch and scontrol do the work.

#include <string>
#include <vector>

#include "hil/harness/campaign/campaign_folder.h"

namespace hil::harness {

struct SlurmOptions {
  std::string partition;   ///< empty: the cluster's default
  int array_tasks = 0;     ///< 0: from runs_per_task
  int runs_per_task = 0;   ///< 0: 10 runs per task (Slurm's per-task overhead is about 1 s)
  int cpus_per_task = 1;   ///< each task runs this many runs at a time
  std::string time_limit;  ///< --time of each task; empty: the partition's
  std::string hil_exe;     ///< absolute path of the hil binary the jobs run
  std::vector<std::string> campaign_args;  ///< FILE and options, as the shards must see them
};

/// The number of array tasks (shards) for `runs` runs. @throws std::invalid_argument when the
/// options contradict each other.
int SlurmShardCount(std::size_t runs, const SlurmOptions& options);

/// Writes DIR/slurm/shards.sbatch and DIR/slurm/merge.sbatch.
void WriteSlurmScripts(const CampaignFolder& folder, const SlurmOptions& options);

struct SlurmSubmission {
  std::string array_job, merge_job;
  std::vector<int> shards;  ///< the array indices submitted
};

/// Submits the array (only `shards`) and the merge job; records both in DIR/slurm/jobs.json.
/// @throws std::runtime_error when sbatch fails (its message included).
SlurmSubmission SubmitSlurm(const CampaignFolder& folder, const std::vector<int>& shards);

/// Waits until the job has ended (scontrol show job), polling every `poll_s`; its final JobState
/// ("COMPLETED", "FAILED", "CANCELLED", …; "GONE" when Slurm no longer knows it).
std::string WaitForSlurmJob(const std::string& job, double poll_s = 1.0);

/// The job's JobState now ("RUNNING", "CANCELLED", …), "GONE" when Slurm no longer knows it, ""
/// when scontrol cannot be run here.
std::string SlurmJobState(const std::string& job);

/// `s` quoted for a POSIX shell.
std::string ShellQuote(const std::string& s);

}  // namespace hil::harness

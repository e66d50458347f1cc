// hil campaign: a Monte Carlo campaign (scenarios × seeds × sweeps) run here (--local), as one
// shard (--shard i/N) or as a Slurm job array (--slurm); `status` and `merge` read its folder.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "hil/harness/campaign/campaign_merge.h"
#include "hil/harness/campaign/campaign_runner.h"
#include "hil/harness/campaign/campaign_slurm.h"
#include "hil/harness/cli/commands.h"
#include "hil/harness/run/folder_lock.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::cli {
namespace {

namespace fs = std::filesystem;
using harness::CampaignFolder;
using nlohmann::json;

struct CampaignArgs {
  CLI::App *cmd = nullptr, *status = nullptr, *merge = nullptr;
  std::string file, out, shard, dir;
  bool local = false, slurm = false, wait = false, allow_partial = false;
  int jobs = 2, nice = 0;
  CLI::Option* nice_opt = nullptr;
  harness::SlurmOptions so;
};

void DeclareSlurm(CLI::App* c, CampaignArgs& a) {
  c->add_flag("--slurm", a.slurm,
              "write DIR/slurm/shards.sbatch (an array task per shard) and merge.sbatch (afterok), "
              "and submit them; again into the same folder: only shards with missing runs");
  c->add_option("--partition", a.so.partition, "Slurm partition (default: the cluster's)");
  c->add_option("--array-tasks", a.so.array_tasks, "array tasks (shards)")
      ->check(CLI::Range(1, 100000));
  c->add_option("--runs-per-task", a.so.runs_per_task, "runs per array task (default 10)")
      ->check(CLI::Range(1, 100000));
  c->add_option("--cpus-per-task", a.so.cpus_per_task,
                "CPUs of each array task, which runs that many runs at a time (default 1)")
      ->check(CLI::Range(1, 256));
  c->add_option("--time", a.so.time_limit, "time limit of each array task (sbatch --time)");
  c->add_flag("--wait", a.wait,
              "wait for the merge job; exit as the merge does (3: runs missing, the status says "
              "which shards)");
}

void Declare(CLI::App& app, CampaignArgs& a) {
  a.cmd = app.add_subcommand(
      "campaign",
      "Run a campaign file (scenarios × seeds × sweeps, criteria across runs) here, as one shard "
      "or on Slurm; merge its records into summary.json, report.md/.html and junit.xml. Exit 0 "
      "pass, 1 fail, 2 bad input, 3 runs missing");
  a.cmd->add_option("FILE", a.file, "campaign file (YAML; vectors/campaigns/README.md)");
  a.cmd->add_option("--out", a.out, "campaign folder (default: runs/campaign-<name>)");
  a.cmd->add_flag("--local", a.local, "run every missing run here, then merge");
  a.cmd->add_option("--shard", a.shard,
                    "run shard I of N (I/N, 1-based): runs k with k mod N = I-1");
  a.cmd->add_option("-j,--jobs", a.jobs, "runs at the same time (--local, --shard)")
      ->check(CLI::Range(1, 256));
  a.nice_opt = a.cmd
                   ->add_option("--nice", a.nice,
                                "nice value of every run (hil run --nice; default: hil run's "
                                "-10), also in the Slurm tasks; 0 leaves the priority as it is")
                   ->check(CLI::Range(-20, 19));
  DeclareSlurm(a.cmd, a);
  a.status = a.cmd->add_subcommand("status",
                                   "Progress of a campaign folder: runs done, and each "
                                   "shard complete, running, failed or killed (with the "
                                   "runs it lacks); exit 0 complete, 3 not");
  a.status->add_option("DIR", a.dir, "campaign folder")->required();
  a.merge = a.cmd->add_subcommand("merge",
                                  "Merge a campaign folder's run records into "
                                  "summary.json, report.md, report.html, junit.xml");
  a.merge->add_option("DIR", a.dir, "campaign folder")->required();
  a.merge->add_flag("--allow-partial", a.allow_partial,
                    "merge even when runs are missing (the report says which; exit 3)");
}

std::optional<harness::CampaignPlan> LoadPlan(const std::string& file) {
  try {
    return harness::PlanCampaign(harness::ReadCampaignFile(file));
  } catch (const harness::ScenarioError& e) {
    std::fprintf(stderr, "hil: invalid campaign: %s\n", e.what());
    return std::nullopt;
  }
}

void WriteState(const std::string& path, const json& state) {
  harness::WriteFileAtomically(path, state.dump(2) + "\n");
}

json StartState(int shard, int shards) {
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  json st{{"state", "running"},
          {"shard", shard > 0 ? std::to_string(shard) + "/" + std::to_string(shards) : "local"},
          {"host", host},
          {"pid", getpid()},
          {"started_unix_s", static_cast<long long>(std::time(nullptr))}};
  const char* job = std::getenv("SLURM_ARRAY_JOB_ID");
  const char* task = std::getenv("SLURM_ARRAY_TASK_ID");
  if (job && task) st["slurm_job"] = std::string(job) + "_" + task;
  return st;
}

// Runs `indices` of the folder with a state file that says running, then finished.
int RunPart(const CampaignFolder& f, const std::vector<std::size_t>& indices, int shard,
            const CampaignArgs& a) {
  const std::string state_path =
      shard > 0 ? harness::ShardStatePath(f.dir, shard) : f.dir + "/shards/local.json";
  json st = StartState(shard, f.shards);
  WriteState(state_path, st);
  harness::RunnerOptions ro;
  ro.hil_exe = SelfExecutable();
  ro.jobs = a.jobs;
  ro.label = st["shard"].get<std::string>() == "local" ? "local"
                                                       : "shard " + st["shard"].get<std::string>();
  ro.live = isatty(STDERR_FILENO) != 0;
  if (*a.nice_opt) ro.nice = a.nice;
  const harness::RunnerResult r = harness::RunCampaignRuns(f, indices, ro);
  st["state"] = "finished";
  st["exit_code"] = 0;
  st["ran"] = r.ran;
  st["skipped"] = r.skipped;
  st["finished_unix_s"] = static_cast<long long>(std::time(nullptr));
  WriteState(state_path, st);
  std::fprintf(stderr, "%s: %zu run(s) ran, %zu already recorded\n", ro.label.c_str(), r.ran,
               r.skipped);
  return kExitPass;
}

int ReportMerge(const CampaignFolder& f, const harness::MergeOutcome& m) {
  if (!m.written) {
    std::fprintf(stderr,
                 "hil: the campaign is incomplete; merge refused (--allow-partial merges "
                 "what is there)\n%s",
                 harness::ProgressText(f, harness::ReadProgress(f)).c_str());
    return m.exit_code;
  }
  const json& s = m.summary;
  std::printf(
      "%s  campaign %s: %zu/%zu run(s), %d passed, %d failed, %d invalid%s  report: "
      "%s/report.md, report.html, summary.json, junit.xml\n",
      s.value("pass", false) ? "PASS" : "FAIL", f.plan.spec.name.c_str(), s["runs"].size(),
      f.plan.runs.size(), s.value("passed", 0), s.value("failed", 0), s.value("invalid", 0),
      s.value("complete", false) ? "" : " (PARTIAL)", f.dir.c_str());
  for (const auto& c : s["criteria"]) {
    std::printf("  [%s] %s\n", c.value("pass", false) ? "PASS" : "FAIL",
                c.value("name", "").c_str());
  }
  return m.exit_code;
}

std::optional<std::pair<int, int>> ParseShard(const std::string& text) {
  int i = 0, n = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &i, &n, &tail) != 2 || n < 1 || i < 1 || i > n)
    return std::nullopt;
  return std::make_pair(i, n);
}

int RunSlurm(const harness::CampaignPlan& plan, const std::string& dir, CampaignArgs& a) {
  int shards = 0;
  std::error_code ec;
  if (!fs::exists(dir + "/campaign.json", ec) || a.so.array_tasks > 0 || a.so.runs_per_task > 0)
    shards = harness::SlurmShardCount(plan.runs.size(), a.so);
  const CampaignFolder f = harness::PrepareCampaignFolder(dir, plan, shards);
  std::vector<int> todo;
  for (const auto& s : harness::ReadProgress(f).shards) {
    if (!s.missing.empty()) todo.push_back(s.shard);
  }
  if (todo.empty()) {
    std::fprintf(stderr, "hil: every run is recorded; merging here\n");
    return ReportMerge(f, harness::MergeCampaign(f, false));
  }
  a.so.hil_exe = SelfExecutable();
  a.so.campaign_args = {a.file};
  if (*a.nice_opt)
    a.so.campaign_args.insert(a.so.campaign_args.end(), {"--nice", std::to_string(a.nice)});
  harness::WriteSlurmScripts(f, a.so);
  const harness::SlurmSubmission sub = harness::SubmitSlurm(f, todo);
  std::printf(
      "submitted %zu array task(s) as job %s (%s/slurm/shards.sbatch) and the merge as job "
      "%s (afterok); progress: hil campaign status %s\n",
      todo.size(), sub.array_job.c_str(), dir.c_str(), sub.merge_job.c_str(), dir.c_str());
  std::fflush(stdout);
  if (!a.wait) return kExitPass;
  const std::string state = harness::WaitForSlurmJob(sub.merge_job);
  const harness::CampaignProgress p = harness::ReadProgress(f);
  if (!p.complete()) {
    std::fprintf(stderr, "hil: merge job %s ended %s; runs are missing:\n%s", sub.merge_job.c_str(),
                 state.c_str(), harness::ProgressText(f, p).c_str());
    return harness::kExitIncomplete;
  }
  std::ifstream in(dir + "/summary.json");
  const json s = json::parse(in, nullptr, false);
  std::printf("merge job %s %s: %s\n", sub.merge_job.c_str(), state.c_str(),
              s.is_object() && s.value("pass", false) ? "PASS" : "FAIL");
  if (!s.is_object()) return harness::kExitIncomplete;
  return s.value("invalid", 0) > 0 ? kExitBadInput : s.value("pass", false) ? kExitPass : kExitFail;
}

int RunFile(CampaignArgs& a) {
  if (a.file.empty()) {
    std::fprintf(stderr, "hil: campaign needs FILE, or status DIR, or merge DIR\n");
    return kExitBadInput;
  }
  if ((a.local ? 1 : 0) + (a.shard.empty() ? 0 : 1) + (a.slurm ? 1 : 0) != 1) {
    std::fprintf(stderr, "hil: give one of --local, --shard I/N or --slurm\n");
    return kExitBadInput;
  }
  const auto plan = LoadPlan(a.file);
  if (!plan) return kExitBadInput;
  const std::string dir = a.out.empty() ? "runs/campaign-" + plan->spec.name : a.out;
  if (a.slurm) return RunSlurm(*plan, dir, a);
  if (a.local) {
    const CampaignFolder f = harness::PrepareCampaignFolder(dir, *plan, 0);
    const harness::FolderLock lock(dir, harness::kCampaignLockName);  // alone in the folder
    std::vector<std::size_t> all(plan->runs.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
    RunPart(f, all, 0, a);
    return ReportMerge(f, harness::MergeCampaign(f, false));
  }
  const auto shard = ParseShard(a.shard);
  if (!shard) {
    std::fprintf(stderr, "hil: --shard expects I/N with 1 <= I <= N, got '%s'\n", a.shard.c_str());
    return kExitBadInput;
  }
  const CampaignFolder f = harness::PrepareCampaignFolder(dir, *plan, shard->second);
  // beside the other shards (each alone with its runs), never beside --local or a merge
  const harness::FolderLock folder(dir, harness::kCampaignLockName, false);
  const harness::FolderLock own(dir + "/shards", "shard-" + std::to_string(shard->first) + ".lock");
  return RunPart(f, harness::ShardRuns(f.plan, shard->first, shard->second), shard->first, a);
}

int Execute(CampaignArgs& a) {
  try {
    if (a.status->parsed()) {
      const CampaignFolder f = harness::LoadCampaignFolder(a.dir);
      const harness::CampaignProgress p = harness::ReadProgress(f);
      std::printf("%s", harness::ProgressText(f, p).c_str());
      return p.complete() ? kExitPass : harness::kExitIncomplete;
    }
    if (a.merge->parsed()) {
      const CampaignFolder f = harness::LoadCampaignFolder(a.dir);
      const harness::FolderLock lock(a.dir, harness::kCampaignLockName);
      return ReportMerge(f, harness::MergeCampaign(f, a.allow_partial));
    }
    return RunFile(a);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace

Subcommand AddCampaign(CLI::App& app) {
  auto a = std::make_shared<CampaignArgs>();
  Declare(app, *a);
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli

#include "hil/harness/campaign/campaign_slurm.h"

#include <unistd.h>

#include <array>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include <sys/wait.h>

namespace hil::harness {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Output {
  int status = -1;
  std::string text;
};

Output RunCommand(const std::string& cmd) {
  Output o;
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return o;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) o.text.append(buf.data(), n);
  const int st = pclose(p);
  o.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128;
  while (!o.text.empty() && (o.text.back() == '\n' || o.text.back() == ' ')) o.text.pop_back();
  return o;
}

std::string Absolute(const std::string& p) { return fs::absolute(p).lexically_normal().string(); }

std::string Header(const CampaignFolder& f, const SlurmOptions& o, const std::string& job,
                   const std::string& log) {
  std::string s = "#!/bin/bash\n# written by hil campaign --slurm for campaign " +
                  f.plan.spec.name + "; submit again with sbatch, as hil does\n";
  s += "#SBATCH --job-name=" + job + "\n";
  s += "#SBATCH --output=" + Absolute(f.dir) + "/logs/" + log + "\n";
  s += "#SBATCH --chdir=" + (f.workdir.empty() ? fs::current_path().string() : f.workdir) + "\n";
  if (!o.partition.empty()) s += "#SBATCH --partition=" + o.partition + "\n";
  return s;
}

}  // namespace

std::string ShellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

int SlurmShardCount(std::size_t runs, const SlurmOptions& o) {
  if (runs == 0) throw std::invalid_argument("the campaign has no runs");
  const int n = static_cast<int>(runs);
  if (o.array_tasks > 0 && o.runs_per_task > 0 && (o.array_tasks - 1) * o.runs_per_task >= n)
    throw std::invalid_argument("--array-tasks " + std::to_string(o.array_tasks) + " with " +
                                "--runs-per-task " + std::to_string(o.runs_per_task) +
                                " leaves array tasks without runs (" + std::to_string(n) +
                                " runs)");
  if (o.array_tasks > 0) return std::min(o.array_tasks, n);
  const int per = o.runs_per_task > 0 ? o.runs_per_task : 10;
  return (n + per - 1) / per;
}

void WriteSlurmScripts(const CampaignFolder& f, const SlurmOptions& o) {
  fs::create_directories(f.dir + "/slurm");
  fs::create_directories(f.dir + "/logs");  // -o folders must exist, or every task fails
  const std::string dir = Absolute(f.dir), name = "hil-" + f.plan.spec.name;
  std::string shards = Header(f, o, name, "shard-%a.out");
  shards += "#SBATCH --array=1-" + std::to_string(f.shards) + "\n";
  shards += "#SBATCH --cpus-per-task=" + std::to_string(o.cpus_per_task) + "\n";
  if (!o.time_limit.empty()) shards += "#SBATCH --time=" + o.time_limit + "\n";
  shards += "exec " + ShellQuote(o.hil_exe) + " campaign";
  for (const auto& a : o.campaign_args) shards += " " + ShellQuote(a);
  shards += " --out " + ShellQuote(dir) + " --shard \"${SLURM_ARRAY_TASK_ID}/" +
            std::to_string(f.shards) + "\" -j " + std::to_string(o.cpus_per_task) + "\n";
  std::string merge = Header(f, o, name + "-merge", "merge.out");
  merge += "exec " + ShellQuote(o.hil_exe) + " campaign merge " + ShellQuote(dir) + "\n";
  std::ofstream(f.dir + "/slurm/shards.sbatch") << shards;
  std::ofstream(f.dir + "/slurm/merge.sbatch") << merge;
}

SlurmSubmission SubmitSlurm(const CampaignFolder& f, const std::vector<int>& shards) {
  SlurmSubmission s;
  s.shards = shards;
  std::string list;
  for (int k : shards) list += (list.empty() ? "" : ",") + std::to_string(k);
  const std::string dir = Absolute(f.dir);
  const Output a = RunCommand("sbatch --parsable --array=" + list + " " +
                              ShellQuote(dir + "/slurm/shards.sbatch"));
  if (a.status != 0 || a.text.empty())
    throw std::runtime_error("sbatch of the shard array failed: " + a.text);
  s.array_job = a.text.substr(0, a.text.find(';'));
  const Output m =
      RunCommand("sbatch --parsable --kill-on-invalid-dep=yes --dependency=afterok:" + s.array_job +
                 " " + ShellQuote(dir + "/slurm/merge.sbatch"));
  if (m.status != 0 || m.text.empty())
    throw std::runtime_error("sbatch of the merge job failed: " + m.text);
  s.merge_job = m.text.substr(0, m.text.find(';'));
  json jobs = json::array();
  std::ifstream in(f.dir + "/slurm/jobs.json");
  if (in) jobs = json::parse(in, nullptr, false);
  if (!jobs.is_array()) jobs = json::array();
  jobs.push_back({{"array_job", s.array_job},
                  {"merge_job", s.merge_job},
                  {"shards", shards},
                  {"submitted_unix_s", static_cast<long long>(std::time(nullptr))}});
  WriteFileAtomically(f.dir + "/slurm/jobs.json", jobs.dump(2) + "\n");
  return s;
}

std::string SlurmJobState(const std::string& job) {
  const Output o = RunCommand("scontrol show job -o " + ShellQuote(job));
  if (o.status == 127 || o.status < 0) return "";
  const std::size_t at = o.text.find("JobState=");
  if (o.status != 0 || at == std::string::npos) return "GONE";
  return o.text.substr(at + 9, o.text.find(' ', at) - at - 9);
}

std::string WaitForSlurmJob(const std::string& job, double poll_s) {
  for (;;) {
    const std::string state = SlurmJobState(job);
    if (state.empty()) return "GONE";
    if (state != "PENDING" && state != "RUNNING" && state != "CONFIGURING" &&
        state != "COMPLETING" && state != "SUSPENDED" && state != "REQUEUED")
      return state;
    std::this_thread::sleep_for(std::chrono::duration<double>(poll_s));
  }
}

}  // namespace hil::harness

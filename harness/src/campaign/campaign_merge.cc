#include "hil/harness/campaign/campaign_merge.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "hil/harness/campaign/campaign_report.h"
#include "hil/harness/campaign/campaign_slurm.h"
#include "hil/harness/campaign/campaign_summary.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json ReadJsonFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return nullptr;
  json j = json::parse(in, nullptr, false);
  return j.is_discarded() ? json(nullptr) : j;
}

std::string ThisHost() {
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  return host;
}

// A shard's state from its state file: running (its process alive, when it runs here), killed (it
// started but its process is gone and it never finished), failed (it finished with runs missing).
void ShardState(const CampaignFolder& f, ShardProgress& s) {
  const json st = ReadJsonFile(ShardStatePath(f.dir, s.shard));
  const std::string log = "logs/shard-" + std::to_string(s.shard) + ".out";
  const bool has_log = fs::exists(fs::path(f.dir) / log);
  if (s.missing.empty()) {
    s.state = "complete";
  } else if (!st.is_object()) {
    s.state = s.done > 0 ? "partial (no shard state: runs from --local?)" : "not started";
  } else if (st.value("state", "") == "finished") {
    s.state = "failed";
    s.detail = "finished with exit code " + std::to_string(st.value("exit_code", -1));
  } else {
    const auto pid = st.value("pid", 0);
    const bool here = st.value("host", "") == ThisHost();
    const bool gone = here && pid > 0 && kill(pid, 0) != 0 && errno == ESRCH;
    s.state = gone ? "killed" : "running";
    s.detail = "started on " + st.value("host", std::string("?")) + " as pid " +
               std::to_string(pid) + (gone ? ", which is gone" : "");
    if (st.contains("slurm_job")) {
      // on another node the pid says nothing: ask Slurm whether the task still runs
      const std::string job = st.value("slurm_job", "");
      const std::string state = SlurmJobState(job);
      s.detail += ", Slurm job " + job + (state.empty() ? "" : " " + state);
      if (!state.empty() && state != "RUNNING" && state != "COMPLETING") s.state = "killed";
    }
  }
  if (has_log) s.detail += (s.detail.empty() ? "log " : "; log ") + log;
}

json TimingJson(const CampaignFolder& f, const std::vector<json>& records) {
  json runs = json::object();
  double total = 0;
  for (const auto& r : records) {
    const double w = r["timing"].value("wall_time_s", 0.0);
    total += w;
    runs[r["run"].value("id", "")] = r["timing"];
  }
  json shards = json::object();
  for (int k = 1; k <= f.shards; ++k) {
    const json st = ReadJsonFile(ShardStatePath(f.dir, k));
    if (st.is_object()) shards[std::to_string(k)] = st;
  }
  const json local = ReadJsonFile(f.dir + "/shards/local.json");
  if (local.is_object()) shards["local"] = local;
  return {{"run_wall_time_total_s", total}, {"runs", runs}, {"shards", shards}};
}

void WriteText(const std::string& path, const std::string& text) {
  WriteFileAtomically(path, text);
}

}  // namespace

CampaignProgress ReadProgress(const CampaignFolder& f) {
  CampaignProgress p;
  p.runs = f.plan.runs.size();
  for (int k = 1; k <= f.shards; ++k) p.shards.push_back({k, 0, 0, {}, "", ""});
  for (const CampaignRun& r : f.plan.runs) {
    ShardProgress& s = p.shards[static_cast<std::size_t>(ShardOfRun(r.index, f.shards) - 1)];
    ++s.runs;
    const auto rec = ReadRecord(f.dir, r);
    if (!rec) {
      s.missing.push_back(r.id);
      continue;
    }
    ++s.done, ++p.done;
    (*rec)["run"].value("exit_code", -1) == 0 ? ++p.passed : ++p.failed;
  }
  for (auto& s : p.shards) ShardState(f, s);
  return p;
}

std::string ProgressText(const CampaignFolder& f, const CampaignProgress& p) {
  char b[512];
  std::snprintf(b, sizeof b,
                "campaign %s: %zu/%zu runs done (%zu passed, %zu failed), %zu shard(s)%s\n",
                f.plan.spec.name.c_str(), p.done, p.runs, p.passed, p.failed, p.shards.size(),
                p.complete() ? ": complete" : "");
  std::string s = b;
  for (const auto& sh : p.shards) {
    std::snprintf(b, sizeof b, "  shard %d/%zu: %zu/%zu done, %s", sh.shard, p.shards.size(),
                  sh.done, sh.runs, sh.state.c_str());
    s += b;
    if (!sh.detail.empty()) s += " (" + sh.detail + ")";
    if (!sh.missing.empty()) {
      s += "; missing runs:";
      for (const auto& id : sh.missing) s += " " + id;
    }
    s += "\n";
  }
  return s;
}

MergeOutcome MergeCampaign(const CampaignFolder& f, bool allow_partial) {
  MergeOutcome out;
  std::vector<json> records;
  json runs = json::array();
  std::vector<std::string> missing;
  for (const CampaignRun& r : f.plan.runs) {
    auto rec = ReadRecord(f.dir, r);
    if (!rec) {
      missing.push_back(r.id);
      continue;
    }
    runs.push_back((*rec)["run"]);
    records.push_back(std::move(*rec));
  }
  if (!missing.empty() && !allow_partial) {
    out.exit_code = kExitIncomplete;
    return out;
  }
  out.summary = SummariseCampaign(f, runs, missing);
  const std::string& dir = f.dir;
  fs::create_directories(dir + "/plots");
  for (const auto& m : out.summary["report_metrics"]) {
    const std::string svg = CdfSvg(out.summary, m.get<std::string>());
    if (!svg.empty()) WriteText(dir + "/plots/cdf_" + m.get<std::string>() + ".svg", svg);
  }
  WriteText(dir + "/summary.json", out.summary.dump(2) + "\n");
  WriteText(dir + "/report.md", CampaignMarkdown(out.summary));
  WriteText(dir + "/report.html", CampaignHtml(out.summary));
  WriteText(dir + "/junit.xml", CampaignJunit(out.summary));
  WriteText(dir + "/timing.json", TimingJson(f, records).dump(2) + "\n");
  out.written = true;
  out.exit_code = !missing.empty()                      ? kExitIncomplete
                  : out.summary.value("invalid", 0) > 0 ? 2
                  : out.summary.value("pass", false)    ? 0
                                                        : 1;
  return out;
}

}  // namespace hil::harness

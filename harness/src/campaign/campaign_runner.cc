#include "hil/harness/campaign/campaign_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <linux/close_range.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>

#include "hil/firmware_emu/wall_time.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A run folder's lock file (run/folder_lock.h kRunLockName; campaign may not include run/):
// made empty before `hil run --out`, it marks the folder, which then holds hil.log, as the run's.
constexpr const char* kRunFolderMark = ".hil-run.lock";

struct Child {
  std::size_t index = 0;
  WallTime started{};
};

std::vector<std::string> RunArgv(const CampaignFolder& f, const CampaignRun& r,
                                 const RunnerOptions& o) {
  const std::string& hil_exe = o.hil_exe;
  const CampaignGroup& g = f.plan.groups[r.group];
  std::vector<std::string> args{hil_exe, "run", g.scenario_file, "--out", f.dir + "/runs/" + r.id};
  if (r.seed) args.insert(args.end(), {"--seed", std::to_string(*r.seed)});
  if (f.plan.spec.short_form) args.emplace_back("--short");
  for (const auto& s : g.settings) args.insert(args.end(), {"--set", s.field + "=" + s.value});
  args.insert(args.end(), f.plan.spec.run_args.begin(), f.plan.spec.run_args.end());
  if (o.nice) args.insert(args.end(), {"--nice", std::to_string(*o.nice)});
  return args;  // with its report.html: the campaign report links every run's (a few kB each)
}

pid_t Start(std::vector<std::string> args, const std::string& log) {
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    // a run ends (as interrupted: its processes stopped, its report written) when the campaign
    // dies, however; the calling thread is the campaign's main thread
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
    }
    // the run inherits none of the campaign's files (as SpawnShell's hosts: shell_spawn.h)
    syscall(SYS_close_range, STDERR_FILENO + 1, ~0U, CLOSE_RANGE_CLOEXEC);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

std::string Tail(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string t = ss.str();
  while (!t.empty() && (t.back() == '\n' || t.back() == '\r')) t.pop_back();
  const std::size_t nl = t.rfind('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

std::string Duration(double s) {
  char b[32];
  if (s < 90)
    std::snprintf(b, sizeof b, "%.0f s", s);
  else if (s < 5400)
    std::snprintf(b, sizeof b, "%.0f min %02.0f s", std::floor(s / 60), std::fmod(s, 60));
  else
    std::snprintf(b, sizeof b, "%.1f h", s / 3600);
  return b;
}

// The progress of this process: done/total over the runs it was given (skipped ones count done).
class Progress {
 public:
  Progress(const RunnerOptions& o, std::size_t total, std::size_t skipped)
      : o_(o), total_(total), done_(skipped), start_(WallNow()) {}
  void Finished(const std::string& id, int code, double wall_s, std::size_t running) {
    ++done_, ++ran_;
    code == 0 ? ++passed_ : ++failed_;
    const double elapsed = Elapsed();
    const double eta = elapsed / static_cast<double>(ran_) * static_cast<double>(total_ - done_);
    char line[512];
    const char* verdict = code == 0 ? "PASS" : code == 1 ? "FAIL" : "ERROR";
    if (o_.live) {
      std::snprintf(line, sizeof line,
                    "\r\033[K%s: %zu/%zu runs done, %zu passed, %zu failed, %zu running, %s "
                    "elapsed, ETA %s (last: %s %s)",
                    o_.label.c_str(), done_, total_, passed_, failed_, running,
                    Duration(elapsed).c_str(), Duration(eta).c_str(), verdict, id.c_str());
    } else {
      std::snprintf(line, sizeof line, "[%zu/%zu] %s %s (%.1f s) %s: ETA %s\n", done_, total_,
                    verdict, id.c_str(), wall_s, o_.label.c_str(), Duration(eta).c_str());
    }
    std::fputs(line, stderr);
    std::fflush(stderr);
  }
  void End() const {
    if (o_.live && ran_ > 0) std::fputs("\n", stderr);
  }
  double Elapsed() const { return ToSeconds(WallNow() - start_); }

 private:
  const RunnerOptions& o_;
  std::size_t total_, done_, ran_ = 0, passed_ = 0, failed_ = 0;
  WallTime start_{};
};

json ReadReport(const std::string& path) {
  std::ifstream rj(path);
  if (!rj) return nullptr;
  json j = json::parse(rj, nullptr, false);
  return j.is_discarded() || !j.is_object() ? json(nullptr) : j;
}

void Record(const CampaignFolder& f, const CampaignRun& r, int code, double wall_s,
            const std::string& label) {
  const std::string run_dir = f.dir + "/runs/" + r.id;
  json rec = MakeRunRecord(f.plan, r, code, ReadReport(run_dir + "/report.json"),
                           Tail(run_dir + "/hil.log"), wall_s);
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  rec["timing"]["host"] = host;
  rec["timing"]["by"] = label;
  WriteFileAtomically(RecordPath(f.dir, r), rec.dump(1) + "\n");
}

}  // namespace

json MakeRunRecord(const CampaignPlan& plan, const CampaignRun& run, int exit_code,
                   const json& report, const std::string& log_tail, double wall_s) {
  const CampaignGroup& g = plan.groups[run.group];
  json settings = json::array();
  for (const auto& s : g.settings) settings.push_back({{"field", s.field}, {"value", s.value}});
  json r{{"id", run.id},
         {"index", run.index},
         {"group", g.id},
         {"settings", settings},
         {"scenario_file", g.scenario_file},
         {"run_dir", "runs/" + run.id},
         {"exit_code", exit_code},
         {"pass", exit_code == 0}};
  if (run.seed) r["seed"] = *run.seed;
  if (report.is_object()) {
    r["scenario"] = report.value("scenario", "");
    r["seed"] = report.value("seed", 0);
    r["metrics"] = report.value("metrics", json::object());
    r["criteria"] = report.value("criteria", json::array());
    r["complete"] = report.value("complete", true);
    // the fault campaign: what each fault injected and how navd saw it (fault_report.h)
    if (report.contains("fault_injections")) r["fault_injections"] = report["fault_injections"];
    if (report.contains("estimator_health")) r["estimator_health"] = report["estimator_health"];
    r["metric_table"] = report.value("metric_table", json::object());
    r["baseline_table"] = report.value("baseline_table", json::object());
    r["outages"] = r["metrics"].value("outages", json::array());
    r["problems"] = report.value("problems", json::array());
  } else {
    r["error"] = log_tail;
  }
  return {{"run", r}, {"timing", {{"wall_time_s", wall_s}}}};
}

RunnerResult RunCampaignRuns(const CampaignFolder& f, const std::vector<std::size_t>& indices,
                             const RunnerOptions& o) {
  RunnerResult result;
  std::vector<std::size_t> todo;
  for (const std::size_t k : indices) {
    if (ReadRecord(f.dir, f.plan.runs.at(k)))
      ++result.skipped;
    else
      todo.push_back(k);
  }
  Progress progress(o, indices.size(), result.skipped);
  std::map<pid_t, Child> running;
  std::size_t next = 0;
  while (next < todo.size() || !running.empty()) {
    while (next < todo.size() && static_cast<int>(running.size()) < std::max(1, o.jobs)) {
      const CampaignRun& r = f.plan.runs[todo[next]];
      const fs::path run_dir = fs::path(f.dir) / "runs" / r.id;
      fs::remove_all(run_dir);  // what a killed attempt left
      fs::create_directories(run_dir);
      // hil.log goes in first: the lock file marks the folder as the run's (run_folder.h), so
      // `hil run --out` takes a folder that is not empty
      std::ofstream((run_dir / kRunFolderMark).string()).flush();
      running[Start(RunArgv(f, r, o), (run_dir / "hil.log").string())] = {todo[next], WallNow()};
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) break;
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const Child c = it->second;
    running.erase(it);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const double wall_s = ToSeconds(WallNow() - c.started);
    const CampaignRun& r = f.plan.runs[c.index];
    Record(f, r, code, wall_s, o.label);
    ++result.ran, ++result.recorded;
    progress.Finished(r.id, code, wall_s, running.size());
  }
  progress.End();
  return result;
}

}  // namespace hil::harness

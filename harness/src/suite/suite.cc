#include "hil/harness/suite/suite.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/report/report.h"
#include "hil/harness/scenario/yaml_reader.h"
#include "hil/harness/suite/suite_report.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

struct Case {
  std::string scenario, out, log;
  std::optional<std::uint64_t> seed;
  int exit_code = -1;
  double wall_s = 0;
  std::int64_t started_ns = 0;
  nlohmann::json report;
};

pid_t Start(const SuiteOptions& opt, const Case& c) {
  std::vector<std::string> args{opt.hil_exe, "run", c.scenario, "--out", c.out};
  if (c.seed) args.insert(args.end(), {"--seed", std::to_string(*c.seed)});
  if (opt.short_form) args.emplace_back("--short");
  args.insert(args.end(), opt.run_args.begin(), opt.run_args.end());
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    const int fd = open(c.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
    }
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

void WriteSuiteJunit(const std::vector<Case>& cases, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"hil suite\">\n";
  for (const Case& c : cases) {
    const std::string name = fs::path(c.out).filename().string();
    std::vector<std::pair<std::string, std::string>> tcs;  // name, failure message ("" = pass)
    if (c.report.is_object()) {
      for (const auto& k : c.report.value("criteria", nlohmann::json::array())) {
        std::string msg;
        if (!k.value("pass", false)) {
          msg = "value " +
                (k["value"].is_number() ? std::to_string(k["value"].get<double>())
                                        : std::string("n/a")) +
                " against threshold " + std::to_string(k.value("threshold", 0.0));
        }
        tcs.emplace_back(k.value("name", "criterion"), msg);
      }
      for (const auto& p : c.report.value("problems", nlohmann::json::array()))
        tcs.emplace_back("run", p.get<std::string>());
    } else {
      tcs.emplace_back("run",
                       "hil run exited with " + std::to_string(c.exit_code) + ": " + Tail(c.log));
    }
    std::size_t failures = 0;
    for (const auto& t : tcs) failures += t.second.empty() ? 0 : 1;
    out << "  <testsuite name=\"" << XmlEscape(name) << "\" tests=\"" << tcs.size()
        << "\" failures=\"" << failures << "\" time=\"" << c.wall_s << "\">\n";
    for (const auto& [tname, msg] : tcs) {
      out << "    <testcase classname=\"" << XmlEscape(name) << "\" name=\"" << XmlEscape(tname)
          << "\">";
      if (!msg.empty()) out << "<failure message=\"" << XmlEscape(msg) << "\"/>";
      out << "</testcase>\n";
    }
    out << "  </testsuite>\n";
  }
  out << "</testsuites>\n";
}

// One case per scenario file and seed, each with its run folder (created here) and log.
std::vector<Case> PlanCases(const std::vector<std::string>& files, const SuiteOptions& opt) {
  std::vector<Case> cases;
  for (const auto& f : files) {
    for (int i = 0; i < std::max(1, opt.repeat); ++i) {
      Case c;
      c.scenario = f;
      std::string stem = fs::path(f).stem().string();
      if (opt.seed || opt.repeat > 1) {
        c.seed = opt.seed.value_or(1) + static_cast<std::uint64_t>(i);
        stem += "-seed" + std::to_string(*c.seed);
      }
      c.out = (fs::path(opt.out_dir) / stem).string();
      fs::create_directories(c.out);
      c.log = c.out + "/hil.log";
      cases.push_back(c);
    }
  }
  return cases;
}

// Runs the cases, at most opt.jobs at a time, and reads each one's exit code and report.json.
void RunCases(std::vector<Case>& cases, const SuiteOptions& opt) {
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, done = 0;
  while (done < cases.size()) {
    while (next < cases.size() && static_cast<int>(running.size()) < std::max(1, opt.jobs)) {
      cases[next].started_ns = link::RealtimePacer::MonotonicNs();
      running[Start(opt, cases[next])] = next;
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) break;
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    Case& c = cases[it->second];
    running.erase(it);
    ++done;
    c.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    c.wall_s = static_cast<double>(link::RealtimePacer::MonotonicNs() - c.started_ns) * 1e-9;
    std::ifstream rj(c.out + "/report.json");
    if (rj) c.report = nlohmann::json::parse(rj, nullptr, false);
    if (c.report.is_discarded()) c.report = nullptr;
    std::fprintf(stderr, "[%zu/%zu] %s %s (%.1f s)\n", done, cases.size(),
                 c.exit_code == 0   ? "PASS"
                 : c.exit_code == 1 ? "FAIL"
                                    : "ERROR",
                 fs::path(c.out).filename().c_str(), c.wall_s);
  }
}

// A case's entry in summary.json: its verdict and, when it wrote one, what its report holds.
nlohmann::json RunJson(const Case& c) {
  nlohmann::json r{{"scenario_file", c.scenario},
                   {"run_dir", c.out},
                   {"exit_code", c.exit_code},
                   {"pass", c.exit_code == 0},
                   {"wall_time_s", c.wall_s}};
  if (c.seed) r["seed"] = *c.seed;
  if (c.report.is_object()) {
    r["scenario"] = c.report.value("scenario", "");
    r["seed"] = c.report.value("seed", 0);
    r["metrics"] = c.report.value("metrics", nlohmann::json::object());
    r["criteria"] = c.report.value("criteria", nlohmann::json::array());
    r["complete"] = c.report.value("complete", true);
    // the fault campaign: what each fault injected and how navd saw it (fault_report.h)
    if (c.report.contains("fault_injections")) r["fault_injections"] = c.report["fault_injections"];
    if (c.report.contains("estimator_health")) r["estimator_health"] = c.report["estimator_health"];
    r["metric_table"] = c.report.value("metric_table", nlohmann::json::object());
    r["baseline_table"] = c.report.value("baseline_table", nlohmann::json::object());
    r["outages"] = r["metrics"].value("outages", nlohmann::json::array());
    r["problems"] = c.report.value("problems", nlohmann::json::array());
  } else {
    r["error"] = Tail(c.log);
  }
  return r;
}

}  // namespace

std::vector<std::string> SuiteScenarios(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error("cannot read the scenario folder " + dir);
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".yaml" || ext == ".yml"))
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

SuiteResult RunSuite(const SuiteOptions& opt) {
  const std::vector<std::string> files = SuiteScenarios(opt.dir);
  std::error_code ec;
  fs::create_directories(opt.out_dir, ec);
  if (ec || access(opt.out_dir.c_str(), W_OK) != 0)
    throw std::runtime_error("cannot write the output folder " + opt.out_dir);
  const std::int64_t suite_start_ns = link::RealtimePacer::MonotonicNs();
  std::vector<SuiteScenarioInfo> infos;
  for (const auto& f : files) {
    SuiteScenarioInfo info;
    info.file = f;
    try {
      info.scenario = LoadScenario(f, opt.short_form);
    } catch (const ScenarioError& e) {
      info.error = e.what();
    }
    infos.push_back(std::move(info));
  }
  std::vector<Case> cases = PlanCases(files, opt);
  RunCases(cases, opt);
  SuiteResult result;
  nlohmann::json summary;
  summary["scenario_dir"] = opt.dir;
  summary["runs"] = nlohmann::json::array();
  for (const Case& c : cases) {
    ++result.runs;
    if (c.exit_code == 0)
      ++result.passed;
    else if (c.exit_code == 1)
      ++result.failed;
    else
      ++result.invalid;
    summary["runs"].push_back(RunJson(c));
  }
  summary["passed"] = result.passed;
  summary["failed"] = result.failed;
  summary["invalid"] = result.invalid;
  summary["pass"] = result.exit_code() == 0;
  summary["short_form"] = opt.short_form;
  summary["seeds"] = std::max(1, opt.repeat);
  summary["jobs"] = opt.jobs;
  summary["wall_time_s"] =
      static_cast<double>(link::RealtimePacer::MonotonicNs() - suite_start_ns) * 1e-9;
  summary["scenarios"] = SummariseScenarios(infos, summary["runs"]);
  std::ofstream(opt.out_dir + "/summary.json") << summary.dump(2) << "\n";
  std::ofstream md(opt.out_dir + "/report.md");
  if (!md) throw std::runtime_error("cannot write " + opt.out_dir + "/report.md");
  md << SuiteMarkdown(summary);
  WriteSuiteJunit(cases, opt.out_dir + "/junit.xml");
  return result;
}

}  // namespace hil::harness

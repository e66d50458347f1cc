// Issue 40.1-40.5 through the real hil binary, the robustness probe's cases: hil killed with
// SIGKILL mid-run (nothing it started survives; a rerun into the same folder gives a clean run's
// bytes), two runs or campaigns into one folder (the second is refused, naming the first), the
// default folder per seed and run, an estimator that floods its stdout or does not read its links,
// values that would run a command through every substitution (and a space in --out), and
// solutions dated outside the run (not a PASS).
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/file.h>
#include <sys/wait.h>

#include "hil/harness/dut/process_group.h"
#include "hil/harness/links/capture_format.h"

#include "cli_runner.h"

namespace hil::test {
namespace {

namespace fs = std::filesystem;
using std::chrono::steady_clock;

std::string Hil() { return BinDir() + "/hil"; }

// A GNSS-only navd scenario on the seed 000 origin.
std::string Scenario(double duration_s, const std::string& name = "safety") {
  return "name: \"" + name + "\"\nduration_s: " + std::to_string(duration_s) +
         "\nseed: 5\norigin: {lat_deg: 35.4796096, lon_deg: 50.5979765, height_m: 1312.0}\n"
         "path: {type: line, heading_deg: 30.0, speed_kmh: 1.6}\n"
         "estimator: {navd_mode: gnss_only, silence_timeout_s: 3}\n";
}

// Starts hil with `args` in `cwd` (stdout+stderr into `log`); returns its pid.
pid_t StartHil(const std::vector<std::string>& args, const std::string& log,
               const std::string& cwd = "") {
  return SpawnLogged(Hil(), args, log, cwd);
}

int WaitExit(pid_t pid, double timeout_s) {
  const auto deadline = steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  while (steady_clock::now() < deadline) {
    if (waitpid(pid, &status, WNOHANG) == pid)
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  ADD_FAILURE() << "hil did not end within " << timeout_s << " s";
  return -1;
}

template <typename F>
bool WaitFor(F&& done, double timeout_s) {
  const auto deadline = steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return done();
}

bool NonEmpty(const std::string& path) {
  std::error_code ec;
  return fs::exists(path, ec) && fs::file_size(path, ec) > 0;
}

// Whether nobody holds the flock of `path` (a missing file holds none).
bool LockFree(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return true;
  const bool free = flock(fd, LOCK_EX | LOCK_NB) == 0;
  close(fd);
  return free;
}

nlohmann::json Report(const std::string& run_dir) {
  const std::string text = ReadFile(run_dir + "/report.json");
  EXPECT_FALSE(text.empty()) << "no report.json in " << run_dir;
  return text.empty() ? nlohmann::json::object() : nlohmann::json::parse(text);
}

// An estimator that writes its pid, leaves a helper in its process group (a grandchild of hil:
// no parent-death signal of its own) and runs navd.
const char* kEstimatorWithHelper =
    "sh -c 'echo $$ > {run_dir}/est.pid; sleep 600 & exec {navd} --config {run_dir}/navd.conf'";

// Issue 40.1: the orphan navd of a killed hil grabbed the ptys of the next run into the folder.
TEST(HilRunSafetyE2eTest, KillNineMidRunLeavesNoProcessAndARerunMatchesACleanRun) {
  TempDir dir("e2e_kill9");
  WriteFile(dir / "s.yaml", Scenario(60));
  const std::string run = dir / "run";
  const pid_t hil = StartHil({"run", dir / "s.yaml", "--out", run, "--mode", "scaled", "--speed",
                              "5", "--estimator", kEstimatorWithHelper},
                             dir / "killed.log");
  ASSERT_TRUE(WaitFor([&] { return NonEmpty(run + "/est.pid"); }, 20))
      << ReadFile(dir / "killed.log");
  std::this_thread::sleep_for(std::chrono::seconds(2));  // 10 s of the scenario
  const pid_t est = std::stoi(ReadFile(run + "/est.pid"));
  const pid_t group = getpgid(est);
  ASSERT_GT(group, 0);
  ASSERT_GE(harness::LiveGroupMembers(group).size(), 2u);  // the shell's navd and its helper
  ASSERT_EQ(kill(hil, SIGKILL), 0);
  EXPECT_EQ(WaitExit(hil, 10), 128 + SIGKILL);
  EXPECT_TRUE(WaitFor([&] { return harness::LiveGroupMembers(group).empty(); }, 10))
      << harness::LiveGroupMembers(group).size() << " processes of the killed run still live";
  // the folder's lock goes once the last process of the run is gone
  EXPECT_TRUE(WaitFor([&] { return LockFree(run + "/.hil-run.lock"); }, 10));

  // the same scenario again into the killed run's folder, and into a fresh one: the same bytes
  const std::string clean = dir / "clean";
  const CommandResult again =
      RunCommand(Hil() + " run " + dir / "s.yaml" + " --out " + run + " --no-html");
  const CommandResult fresh =
      RunCommand(Hil() + " run " + dir / "s.yaml" + " --out " + clean + " --no-html");
  EXPECT_EQ(again.exit_code, 0) << again.out;
  EXPECT_EQ(fresh.exit_code, 0) << fresh.out;
  EXPECT_EQ(ReadFile(run + "/estimate.csv"), ReadFile(clean + "/estimate.csv"));
  EXPECT_EQ(ReadFile(run + "/captures/ttyGPS.cap"), ReadFile(clean + "/captures/ttyGPS.cap"));
  EXPECT_EQ(Report(run)["metrics"], Report(clean)["metrics"]);
}

// Issue 40.3: two runs into one --out read each other's ptys.
TEST(HilRunSafetyE2eTest, ASecondRunIntoABusyFolderIsRefusedNamingTheFirst) {
  TempDir dir("e2e_busy");
  WriteFile(dir / "s.yaml", Scenario(60));
  const std::string run = dir / "run";
  const pid_t first = StartHil({"run", dir / "s.yaml", "--out", run, "--mode", "scaled", "--speed",
                                "10", "--estimator", kEstimatorWithHelper},
                               dir / "first.log");
  ASSERT_TRUE(WaitFor([&] { return NonEmpty(run + "/est.pid"); }, 20));
  const CommandResult second = RunCommand(Hil() + " run " + dir / "s.yaml" + " --out " + run);
  EXPECT_EQ(second.exit_code, 2) << second.out;
  EXPECT_NE(second.out.find(run + " is in use by another hil (pid " + std::to_string(first) + ": " +
                            Hil() + " run "),
            std::string::npos)
      << second.out;
  kill(first, SIGTERM);
  EXPECT_EQ(WaitExit(first, 30), 128 + SIGTERM);  // interrupted, README exit codes
  EXPECT_FALSE(Report(run).empty());              // the first run's report, not disturbed
}

// Issue 40.3: two seeds of one scenario shared runs/<name>; a rerun overwrote the last run.
TEST(HilRunSafetyE2eTest, TheDefaultFolderIsOnePerSeedAndRun) {
  TempDir dir("e2e_default");
  WriteFile(dir / "s.yaml", Scenario(5, "dflt"));
  const std::string cd = "cd " + dir.str() + " && " + Hil() + " run s.yaml --no-html";
  for (const std::string& args : {std::string(), std::string(), std::string(" --seed 7")}) {
    const CommandResult r = RunCommand(cd + args);
    EXPECT_EQ(r.exit_code, 0) << r.out;
  }
  EXPECT_TRUE(fs::exists(dir / "runs/dflt-seed5/report.json"));
  EXPECT_TRUE(fs::exists(dir / "runs/dflt-seed5-2/report.json"));
  EXPECT_TRUE(fs::exists(dir / "runs/dflt-seed7/report.json"));
  EXPECT_EQ(Report(dir / "runs/dflt-seed7")["seed"], 7);
}

// Issue 40: `--out /` was accepted and overwrote files. A folder of other files and the home
// folder are refused with exit 2 before anything is written; a previous run's folder
// (report.json) takes a rerun.
TEST(HilRunSafetyE2eTest, AnOutputFolderOfOtherFilesIsRefused) {
  TempDir dir("e2e_out_refused");
  WriteFile(dir / "s.yaml", Scenario(10, "outref"));
  fs::create_directories(dir / "mine");
  WriteFile(dir / "mine/notes.txt", "precious");
  fs::create_directories(dir / "home");
  const std::string env = "HOME=" + dir / "home" + " ";
  // (`/` itself is checked in run_folder_test: a regression here would write into /)
  for (const std::string& out : {dir / "mine", dir / "home"}) {
    const CommandResult r =
        RunCommand(env + Hil() + " run " + dir / "s.yaml" + " --no-html --out " + out);
    EXPECT_EQ(r.exit_code, 2) << out << "\n" << r.out;
    EXPECT_NE(r.out.find("refusing the output folder " + out), std::string::npos) << r.out;
  }
  EXPECT_EQ(ReadFile(dir / "mine/notes.txt"), "precious");
  EXPECT_FALSE(fs::exists(dir / "mine/report.json"));
  EXPECT_TRUE(fs::is_empty(dir / "home"));
  // a run's own folder takes a rerun
  for (int k = 0; k < 2; ++k) {
    const CommandResult r =
        RunCommand(Hil() + " run " + dir / "s.yaml" + " --no-html --out " + dir / "run");
    EXPECT_EQ(r.exit_code, 0) << r.out;
  }
}

// Issue 40.3: two `campaign --local` into one folder ran everything twice.
TEST(HilRunSafetyE2eTest, ASecondCampaignIntoABusyFolderIsRefused) {
  TempDir dir("e2e_busy_campaign");
  WriteFile(dir / "s.yaml", Scenario(20));
  WriteFile(dir / "c.yaml",
            "name: busy\nscenarios: [s.yaml]\nseeds: {from: 1, to: 2}\n"
            "run: {mode: scaled, speed: 5}\n");
  const std::string out = dir / "campaign";
  const pid_t first =
      StartHil({"campaign", dir / "c.yaml", "--local", "-j", "1", "--out", out}, dir / "first.log");
  ASSERT_TRUE(WaitFor([&] { return NonEmpty(out + "/shards/local.json"); }, 20));
  const CommandResult second =
      RunCommand(Hil() + " campaign " + dir / "c.yaml" + " --local --out " + out);
  EXPECT_EQ(second.exit_code, 2) << second.out;
  EXPECT_NE(second.out.find(out + " is in use by another hil (pid " + std::to_string(first)),
            std::string::npos)
      << second.out;
  const int code = WaitExit(first, 120);
  EXPECT_TRUE(code == 0 || code == 1) << ReadFile(dir / "first.log");
}

// Issue 40.2: `cat /dev/urandom` as the estimator froze a virtual run and wrote 4.2 GB.
TEST(HilRunSafetyE2eTest, AnEstimatorFloodingItsOutputStopsTheRunWithABoundedFile) {
  TempDir dir("e2e_flood");
  WriteFile(dir / "s.yaml", Scenario(60));
  const std::string run = dir / "run";
  const pid_t hil = StartHil(
      {"run", dir / "s.yaml", "--out", run, "--no-html", "--estimator", "cat /dev/urandom"},
      dir / "log");
  const int code = WaitExit(hil, 120);
  const std::string log = ReadFile(dir / "log");
  EXPECT_EQ(code, 1) << log;
  EXPECT_NE(log.find("the estimator floods its output"), std::string::npos) << log;
  const nlohmann::json r = Report(run);
  EXPECT_FALSE(r.value("complete", true));
  EXPECT_FALSE(r.value("pass", true));
  // at most what 60 s of a run may keep: 16 MiB + 64 KiB per emulated second
  EXPECT_LE(fs::file_size(run + "/estimate.jsonl"), (16u << 20) + 60u * (64u << 10));
}

// Issue 40.2: a talking estimator that never opens its links is no more a PASS than a silent one.
TEST(HilRunSafetyE2eTest, AnEstimatorThatTalksButNeverReadsStopsTheRun) {
  TempDir dir("e2e_noread");
  WriteFile(dir / "s.yaml", Scenario(60));
  const std::string run = dir / "run";
  const pid_t hil =
      StartHil({"run", dir / "s.yaml", "--out", run, "--no-html", "--silence-timeout", "2",
                "--estimator", "sh -c 'while :; do echo chatter; sleep 0.05; done'"},
               dir / "log");
  const int code = WaitExit(hil, 60);
  const std::string log = ReadFile(dir / "log");
  EXPECT_EQ(code, 1) << log;
  EXPECT_NE(log.find("the estimator stopped reading"), std::string::npos) << log;
  EXPECT_FALSE(Report(run).value("complete", true));
  // real time has no gate: the link it never read is the problem
  const pid_t scaled = StartHil(
      {"run", dir / "s.yaml", "--out", dir / "scaled", "--no-html", "--mode", "scaled", "--speed",
       "20", "--estimator", "sh -c 'while :; do echo chatter; sleep 0.05; done'"},
      dir / "scaled.log");
  const int scaled_code = WaitExit(scaled, 60);
  const std::string scaled_log = ReadFile(dir / "scaled.log");
  EXPECT_EQ(scaled_code, 1) << scaled_log;
  EXPECT_NE(scaled_log.find("the estimator never read ttyGPS"), std::string::npos) << scaled_log;
}

// Issue 40.4: --out, a scenario's name, a path file's name: each ran a command of ours.
class Injection : public ::testing::Test {
 protected:
  void SetUp() override { fs::remove(marker_); }
  void TearDown() override { fs::remove(marker_); }
  std::string Hostile() const { return "a b$(touch " + marker_ + ")`touch " + marker_ + "`'"; }
  const std::string marker_ = "/tmp/hil_pwned_" + std::to_string(getpid());
};

TEST_F(Injection, ThroughRunDirAndASpaceInOut) {
  TempDir dir("e2e_inject_out");
  WriteFile(dir / "s.yaml", Scenario(10));
  const std::string run = dir / Hostile();
  // the scenario's own command ({navd} --config {run_dir}/navd.conf), and one of an inner shell
  for (const std::string& est :
       {std::string(), std::string(" --estimator \"") + "sh -c 'exec {navd} --config "
                                                        "{run_dir}/navd.conf'\""}) {
    const std::string cmd = Hil() + " run " + dir / "s.yaml" + " --no-html --out '" + dir.str() +
                            "/a b$(touch " + marker_ + ")`touch " + marker_ + "`'\\''" + "'" + est;
    const CommandResult r = RunCommand(cmd);
    EXPECT_EQ(r.exit_code, 0) << cmd << "\n" << r.out;
    EXPECT_GT(Report(run).value("metrics", nlohmann::json::object()).value("samples", 0), 5);
    EXPECT_FALSE(fs::exists(marker_)) << "a substitution ran a command: " << cmd;
  }
}

TEST_F(Injection, ThroughTheScenarioNameInTheDefaultFolder) {
  TempDir dir("e2e_inject_name");
  WriteFile(dir / "s.yaml", Scenario(10, "n$(touch " + marker_ + ") x"));
  const CommandResult r = RunCommand("cd " + dir.str() + " && " + Hil() + " run s.yaml --no-html");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_FALSE(fs::exists(marker_)) << r.out;
  EXPECT_TRUE(fs::exists(dir / "runs/n__touch__tmp_hil_pwned_" + std::to_string(getpid()) +
                         "__x-seed5/report.json"))
      << r.out;
}

// `text` with every `from` character replaced by `to`.
std::string Replaced(const std::string& text, char from, const std::string& to) {
  std::string out;
  for (const char c : text) out += c == from ? to : std::string(1, c);
  return out;
}

TEST_F(Injection, ThroughThePathFileOfAClosedLoop) {
  TempDir dir("e2e_inject_path");
  // a file name holds no slash: the commands would touch `pwned` in hil's folder (here `dir`)
  const std::string path = dir / "p q$(touch pwned)`touch pwned`'.path";
  fs::copy_file(SourceDir() + "/vectors/paths/ab_line_east_300m.path", path);
  const std::string scenario =
      SourceDir() + "/vectors/scenarios/closed_loop/diff_drive_serial.yaml";
  // --set takes a YAML value (single-quoted: '' for a quote), given to sh in '...'
  const std::string set = "closed_loop.path_file='" + Replaced(path, '\'', "''") + "'";
  const CommandResult r =
      RunCommand("cd " + dir.str() + " && " + Hil() + " run " + scenario +
                 " --no-html --set duration_s=12 --set evaluation.from_s=5 --set '" +
                 Replaced(set, '\'', "'\\''") + "' --out run");
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.out;
  EXPECT_FALSE(fs::exists(dir / "pwned")) << r.out;
  const nlohmann::json rep = Report(dir / "run");
  EXPECT_NE(rep["closed_loop"].value("controller_command", "").find("p q$(touch pwned)"),
            std::string::npos)
      << rep["closed_loop"];
  EXPECT_GT(rep["closed_loop"].value("motor_commands", 0), 10)
      << ReadFile(dir / "run/controller.log");
}

// Issue 40: an interrupted closed loop claimed the whole duration simulated and scored the path
// tracking past the stop (the truth's replay of commands never given). It exits 130, reports the
// emulated time it reached, and scores at most the truth samples (10 Hz) up to there.
TEST(HilRunSafetyE2eTest, AnInterruptedClosedLoopScoresNothingPastTheStop) {
  TempDir dir("e2e_interrupt_loop");
  const std::string scenario =
      SourceDir() + "/vectors/scenarios/closed_loop/diff_drive_serial.yaml";
  const std::string run = dir / "run";
  const pid_t hil =
      StartHil({"run", scenario, "--no-html", "--mode", "scaled", "--speed", "10", "--set",
                "duration_s=400", "--set", "evaluation.from_s=0", "--out", run},
               dir / "log");
  // stopped once the loop runs: the base has answered some control ticks
  ASSERT_TRUE(WaitFor([&] { return NonEmpty(run + "/estimate.jsonl"); }, 30))
      << ReadFile(dir / "log");
  std::this_thread::sleep_for(std::chrono::seconds(2));
  kill(hil, SIGINT);
  const int code = WaitExit(hil, 60);
  EXPECT_EQ(code, 130) << ReadFile(dir / "log");
  const nlohmann::json r = Report(run);
  const double sim_s = r.value("sim_time_s", 0.0);
  EXPECT_GT(sim_s, 0.0);
  EXPECT_LT(sim_s, 399.0) << "the report claims the whole duration simulated";
  ASSERT_TRUE(r.contains("tracking")) << r;
  // the emulated time the run reached, from what it sent: the captures' last records
  double reached_s = 0;
  for (const auto& e : fs::directory_iterator(run + "/captures")) {
    for (const harness::CaptureRecord& rec : harness::ReadCapture(e.path().string()).records)
      reached_s = std::max(reached_s, static_cast<double>(rec.t_emu_ns) * 1e-9);
  }
  EXPECT_LE(sim_s, reached_s + 1.0);
  const int samples = r["tracking"].value("samples", -1);
  EXPECT_GE(samples, 0) << r["tracking"];
  EXPECT_LE(samples, static_cast<int>(reached_s * 10) + 11)
      << "tracking scored past the stop at t = " << reached_s << " s";
}

// Issue 40.5: solutions dated ten years ahead, or at the largest time stamp, were dropped without
// a word, and the run passed.
TEST(HilRunSafetyE2eTest, SolutionsDatedOutsideTheRunAreAProblemNotAPass) {
  TempDir dir("e2e_dates");
  WriteFile(dir / "s.yaml", Scenario(10));
  // reads its link (so the run goes on), writes 20 solutions at `tov` and waits
  const auto estimator = [](const std::string& tov) {
    return "sh -c 'cat {ttyGPS} > /dev/null & i=0; while [ $i -lt 20 ]; do echo "
           "\"{\\\"tov_unix_ns\\\": " +
           tov +
           ", \\\"lat_deg\\\": 35.4796096, \\\"lon_deg\\\": 50.5979765}\"; i=$((i+1)); done; "
           "wait'";
  };
  // 2026-01-01 + 10 years, and INT64_MAX
  for (const std::string tov : {"2082758400000000000", "9223372036854775807"}) {
    const std::string run = dir / ("run" + tov.substr(0, 3));
    const pid_t hil =
        StartHil({"run", dir / "s.yaml", "--out", run, "--no-html", "--estimator", estimator(tov)},
                 dir / "log");
    const int code = WaitExit(hil, 60);
    const std::string log = ReadFile(dir / "log");
    EXPECT_EQ(code, 1) << log;
    EXPECT_NE(log.find("20 of 20 solutions are dated outside the run"), std::string::npos) << log;
    EXPECT_NE(log.find("no solution was scored"), std::string::npos) << log;
    const nlohmann::json r = Report(run);
    EXPECT_FALSE(r.value("pass", true));
    EXPECT_EQ(r["estimator"].value("solutions_outside_run", 0), 20);
  }
}

}  // namespace
}  // namespace hil::test

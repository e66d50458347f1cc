// hil run --lockstep end to end: a host driver that lives by the wall clock (ACK timeouts of
// 250 ms, 20 ms waits before each read, clock_gettime stamps: ubx_timeout_driver.cc, as PX4's
// u-blox driver) configures the emulated NEO-5M of default_ubx_configure. On hil's clock its
// dialogue and every byte of both directions are the same in every run, and the clock it stamps
// each read with is the emulated time the bytes it read had arrived by: the bytes read up to a
// stamp are exactly the bytes whose last bit had left the UART by then. The last run shares the
// machine with a busy process. The closed loop (navd and guidanced) is held to the same.
#include <signal.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "cli_runner.h"

namespace hil::test {
namespace {

// CLOCK_MONOTONIC's reading at emulated t = 0 (lockstep_shared.h kMonotonicBaseNs).
constexpr std::int64_t kMonotonicBaseNs = 1'000'000'000'000;
constexpr int kRuns = 3;

std::string Unhex(const std::string& hex) {
  std::string out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
    out += static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16));
  return out;
}

// The tx records of a capture: (emulated end of the last byte, bytes).
std::vector<std::pair<std::int64_t, std::string>> TxChunks(const std::string& cap) {
  std::vector<std::pair<std::int64_t, std::string>> out;
  std::istringstream in(cap);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string dir, name, data;
    std::int64_t t = 0, period = 0, wall = 0;
    if (!(f >> dir >> t >> period >> wall >> name >> data) || dir != "tx") continue;
    const std::string bytes = Unhex(data);
    out.emplace_back(t + period * static_cast<std::int64_t>(bytes.size()), bytes);
  }
  return out;
}

// The driver's reads: (emulated time of its stamp, bytes).
std::vector<std::pair<std::int64_t, std::string>> Reads(const std::string& log) {
  std::vector<std::pair<std::int64_t, std::string>> out;
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    std::int64_t stamp = 0;
    std::string hex;
    if (f >> stamp >> hex) out.emplace_back(stamp - kMonotonicBaseNs, Unhex(hex));
  }
  return out;
}

// A process that keeps one CPU busy until it is killed.
pid_t StartBusyProcess() {
  const pid_t pid = fork();
  if (pid == 0) {
    volatile unsigned long n = 0;
    for (;;) n = n + 1;
  }
  return pid;
}

// Run 0's copy of each file of `files` in run folder `out` is kept in `first` (and must not be
// empty); a later run's must equal it (`what`: how that run differs, for the message).
void KeepOrCompare(const std::string& out, int run, std::initializer_list<const char*> files,
                   std::map<std::string, std::string>& first, const std::string& what) {
  for (const char* f : files) {
    const std::string text = ReadFile(out + "/" + f);
    if (run == 0) {
      first[f] = text;
      EXPECT_FALSE(text.empty()) << f;
    } else {
      EXPECT_TRUE(text == first[f]) << "run " << run << ": " << f << " differs " << what;
    }
  }
}

// Runs the driver as the estimator into `out`; `loaded`: beside a busy process, at its priority
// (at hil's default nice -10 the busy process would hardly disturb it); `preload_also`: a library
// the driver preloads after hil's.
CommandResult RunDriver(const std::string& out, bool loaded, const std::string& preload_also = "") {
  const std::string scenario = SourceDir() + "/vectors/scenarios/default_ubx_configure.yaml";
  const std::string driver =
      (preload_also.empty() ? "" : "LD_PRELOAD=\"$LD_PRELOAD:" + preload_also + "\" ") +
      HIL_UBX_TIMEOUT_DRIVER " {ttyGPS} {run_dir}/reads.log";
  const pid_t busy = loaded ? StartBusyProcess() : 0;
  const CommandResult r =
      RunCommand(BinDir() + "/hil run " + scenario + " --lockstep --no-html --set duration_s=40" +
                 " --estimator '" + driver + "' --out " + out + (loaded ? " --nice 0" : ""));
  if (busy > 0) {
    kill(busy, SIGKILL);
    waitpid(busy, nullptr, 0);
  }
  return r;
}

TEST(LockstepDeterminismE2E, WallClockDriverGivesTheSameBytesAndStampsTheirArrival) {
  TempDir dir("lockstep_e2e");
  std::map<std::string, std::string> first;
  for (int run = 0; run < kRuns; ++run) {
    const std::string out = dir / ("run" + std::to_string(run));
    const CommandResult r = RunDriver(out, run == kRuns - 1);
    ASSERT_LE(r.exit_code, 1) << r.out;
    const auto report = nlohmann::json::parse(ReadFile(out + "/report.json"));
    ASSERT_TRUE(report.contains("lockstep")) << r.out;
    EXPECT_FALSE(report["lockstep"].contains("fallback")) << report["lockstep"].dump();
    ASSERT_FALSE(report["lockstep"]["processes"].empty());
    EXPECT_EQ(report["lockstep"]["processes"][0]["clock"], "emulated");
    EXPECT_EQ(report["lockstep"]["processes"][0]["name"], "ubx_timeout_dri");
    EXPECT_TRUE(report["complete"].get<bool>()) << r.out;
    KeepOrCompare(out, run, {"captures/ttyGPS.cap", "reads.log", "estimate.jsonl"}, first,
                  "from run 0's");
  }
  // the driver configured the receiver: every command acknowledged, UBX solutions came
  const std::string log = first["reads.log"];
  EXPECT_NE(log.find(" CMD "), std::string::npos);
  EXPECT_EQ(log.find("timed-out"), std::string::npos) << log.substr(0, 2000);
  EXPECT_FALSE(first["estimate.jsonl"].empty());

  // its first command, written at its start, is taken at t = 0 (the first turn waits for the
  // start-up, whether the program has started to wait before hil looks or not)
  EXPECT_NE(first["captures/ttyGPS.cap"].find("\nrx 0 0 0 host "), std::string::npos);

  // its clock is the bytes' emulated arrival: what it read up to each stamp is exactly what had
  // left the UART by then
  const auto chunks = TxChunks(first["captures/ttyGPS.cap"]);
  const auto reads = Reads(log);
  ASSERT_GT(reads.size(), 100u);
  std::string sent, read;
  std::size_t next_chunk = 0;
  for (std::size_t i = 0; i < reads.size(); ++i) {
    const auto& [t, bytes] = reads[i];
    read += bytes;
    while (next_chunk < chunks.size() && chunks[next_chunk].first <= t)
      sent += chunks[next_chunk++].second;
    ASSERT_EQ(read.size(), sent.size()) << "read " << i << " stamped at t = " << t << " ns";
  }
  EXPECT_TRUE(read == sent);
}

// The driver held back 300 ms of wall time in its start-up, where the library claims its main
// thread's slot (start_delay_shim.cc: as if the machine descheduled it there), gives the bytes of
// a run that was not: hil waits for a program it sees until it first waits, however slow.
TEST(LockstepDeterminismE2E, DriverDescheduledAtItsStartGivesTheSameBytes) {
  TempDir dir("lockstep_start_e2e");
  std::map<std::string, std::string> first;
  for (int run = 0; run < 2; ++run) {
    const std::string out = dir / ("run" + std::to_string(run));
    const CommandResult r = RunDriver(out, false, run == 1 ? HIL_START_DELAY_SHIM : "");
    ASSERT_LE(r.exit_code, 1) << r.out;
    const auto report = nlohmann::json::parse(ReadFile(out + "/report.json"));
    ASSERT_TRUE(report.contains("lockstep")) << r.out;
    EXPECT_FALSE(report["lockstep"].contains("fallback")) << report["lockstep"].dump();
    KeepOrCompare(out, run, {"captures/ttyGPS.cap", "reads.log", "estimate.jsonl"}, first,
                  "when the driver starts late");
    EXPECT_NE(ReadFile(out + "/captures/ttyGPS.cap").find("\nrx 0 0 0 host "), std::string::npos)
        << "run " << run << ": its first command was not taken at t = 0";
  }
}

// A read-only driver (an open loop): hil writes ahead and the driver's library moves its clock
// from arrival to arrival (engine/lookahead_writer.h). What it reads, when its clock says it
// read it, and every byte hil sent are those of one host turn per message (--no-lookahead), in
// every run, also beside a busy process.
TEST(LockstepDeterminismE2E, ReadOnlyDriverWithLookaheadSeesWhatATurnPerMessageShows) {
  TempDir dir("lockstep_lookahead_e2e");
  const std::string scenario = SourceDir() + "/vectors/scenarios/default_ubx_configure.yaml";
  const std::string driver = HIL_UBX_TIMEOUT_DRIVER " {ttyGPS} {run_dir}/reads.log --listen";
  std::map<std::string, std::string> first;
  const char* runs[] = {"", " --no-lookahead", ""};
  for (int run = 0; run < 3; ++run) {
    const std::string out = dir / ("run" + std::to_string(run));
    const pid_t busy = run == 2 ? StartBusyProcess() : 0;
    const CommandResult r = RunCommand(
        BinDir() + "/hil run " + scenario + " --lockstep --no-html --set duration_s=60" +
        runs[run] + " --estimator '" + driver + "' --out " + out + (busy ? " --nice 0" : ""));
    if (busy > 0) {
      kill(busy, SIGKILL);
      waitpid(busy, nullptr, 0);
    }
    ASSERT_LE(r.exit_code, 1) << r.out;
    const auto report = nlohmann::json::parse(ReadFile(out + "/report.json"));
    ASSERT_TRUE(report.contains("lockstep")) << r.out;
    EXPECT_FALSE(report["lockstep"].contains("fallback")) << report["lockstep"].dump();
    EXPECT_EQ(report["lockstep"]["lookahead"].get<bool>(), run != 1) << "run " << run;
    KeepOrCompare(out, run, {"captures/ttyGPS.cap", "reads.log"}, first, "from run 0's");
  }
  // its stamps are the bytes' arrival: what it read up to each stamp had left the UART by then,
  // all of it (hil wrote the bytes long before)
  const auto chunks = TxChunks(first["captures/ttyGPS.cap"]);
  const auto reads = Reads(first["reads.log"]);
  ASSERT_GT(reads.size(), 100u);
  std::string sent, read;
  std::size_t next_chunk = 0;
  for (std::size_t i = 0; i < reads.size(); ++i) {
    const auto& [t, bytes] = reads[i];
    read += bytes;
    while (next_chunk < chunks.size() && chunks[next_chunk].first <= t)
      sent += chunks[next_chunk++].second;
    ASSERT_EQ(read.size(), sent.size()) << "read " << i << " stamped at t = " << t << " ns";
  }
  EXPECT_TRUE(read == sent);
}

// A host that does not load the library (here a shell loop: the shell is not preloaded, and it
// starts no program) is paced by the /proc probe after 6 s, and report.json says so.
TEST(LockstepDeterminismE2E, HostWithoutTheLibraryFallsBackToTheProbe) {
  TempDir dir("lockstep_fallback_e2e");
  const std::string out = dir / "run";
  const CommandResult r = RunCommand(
      BinDir() + "/hil run " + SourceDir() +
      "/vectors/scenarios/default.yaml --short --lockstep --no-html --silence-timeout 2" +
      " --estimator 'while read -r l; do :; done < {ttyGPS}' --out " + out);
  EXPECT_NE(r.out.find("did not load libhil_lockstep.so"), std::string::npos) << r.out;
  const auto report = nlohmann::json::parse(ReadFile(out + "/report.json"));
  ASSERT_TRUE(report.contains("lockstep")) << r.out;
  EXPECT_TRUE(report["lockstep"].contains("fallback"));
  ASSERT_EQ(report["lockstep"]["processes"].size(), 1u);
  EXPECT_EQ(report["lockstep"]["processes"][0]["clock"], "probe");
  EXPECT_EQ(report["lockstep"]["turns"], 0);
}

// Closed loop on the clock: navd and guidanced (the controller reads navd's solutions from a FIFO,
// a link hil does not write: the wake-ups between the programs) both load the library, and two
// runs, the second beside a busy process, give the same bytes on every link and the same
// solutions.
TEST(LockstepDeterminismE2E, ClosedLoopNavdAndGuidancedOnTheClock) {
  TempDir dir("lockstep_closed_e2e");
  const std::string scenario =
      SourceDir() + "/vectors/scenarios/closed_loop/diff_drive_serial.yaml";
  std::map<std::string, std::string> first;
  for (int run = 0; run < 2; ++run) {
    const std::string out = dir / ("run" + std::to_string(run));
    const pid_t busy = run == 1 ? StartBusyProcess() : 0;
    const CommandResult r =
        RunCommand(BinDir() + "/hil run " + scenario + " --short --lockstep --no-html --out " +
                   out + (run == 1 ? " --nice 0" : ""));
    if (busy > 0) {
      kill(busy, SIGKILL);
      waitpid(busy, nullptr, 0);
    }
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto report = nlohmann::json::parse(ReadFile(out + "/report.json"));
    ASSERT_TRUE(report.contains("lockstep")) << r.out;
    EXPECT_FALSE(report["lockstep"].contains("fallback")) << report["lockstep"].dump();
    std::string names;
    for (const auto& p : report["lockstep"]["processes"]) {
      EXPECT_EQ(p["clock"], "emulated");
      names += p["name"].get<std::string>() + " ";
    }
    EXPECT_NE(names.find("navd"), std::string::npos) << names;
    EXPECT_NE(names.find("guidanced"), std::string::npos) << names;
    KeepOrCompare(
        out, run,
        {"captures/ttyGPS.cap", "captures/ttyIMU.cap", "captures/ttyBASE.cap", "estimate.jsonl"},
        first, "from run 0's");
  }
}

// The library's descriptor cache (harness/src/preload/descriptor_cache.h) changes nothing the
// programs do: the closed loop over the SLCAN adapter (guidanced writes its commands to a link,
// navd's solutions reach it through a FIFO) gives the same bytes on every link, the same solutions
// and the same metrics with the cache and without it (HIL_LOCKSTEP_FD_CACHE=0), with a fraction
// of the lookups.
TEST(LockstepDeterminismE2E, DescriptorCacheKeepsTheClosedLoopsBytes) {
  TempDir dir("lockstep_fd_cache_e2e");
  const std::string scenario =
      SourceDir() + "/vectors/scenarios/closed_loop/tractor_autosteer_slcan.yaml";
  std::map<std::string, std::string> first;
  std::uint64_t lookups[2] = {0, 0};
  nlohmann::json metrics[2];
  for (int run = 0; run < 2; ++run) {
    const std::string out = dir / ("run" + std::to_string(run));
    const CommandResult r =
        RunCommand(std::string(run == 1 ? "HIL_LOCKSTEP_FD_CACHE=0 " : "") + BinDir() +
                   "/hil run " + scenario + " --short --lockstep --no-html --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const auto report = nlohmann::json::parse(ReadFile(out + "/report.json"));
    ASSERT_TRUE(report.contains("lockstep")) << r.out;
    EXPECT_FALSE(report["lockstep"].contains("fallback")) << report["lockstep"].dump();
    lookups[run] = report["lockstep"]["descriptor_lookups"].get<std::uint64_t>();
    metrics[run] = {report["metrics"], report["tracking"], report["criteria"]};
    KeepOrCompare(
        out, run,
        {"captures/ttyCAN.cap", "captures/ttyGPS.cap", "captures/ttyIMU.cap", "estimate.jsonl"},
        first, "without the cache");
  }
  EXPECT_EQ(metrics[0], metrics[1]);
  EXPECT_GT(lookups[0], 0u);
  EXPECT_LT(lookups[0] * 100, lookups[1])
      << "with the cache " << lookups[0] << ", without " << lookups[1];
}

}  // namespace
}  // namespace hil::test

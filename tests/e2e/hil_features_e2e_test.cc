// End to end through the real hil binary: validate, suite, run modes (byte identity across
// virtual/scaled/real time), estimator hangs, fault timeline effects, output adapters, report.html.
#include <dirent.h>
#include <unistd.h>

#include <filesystem>
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "shared_vectors.h"

namespace hil::test {
namespace {

const std::string kOrigin =
    "origin: {lat_deg: 35.4796096, lon_deg: 50.5979765, height_m: 1312.0}\n";

std::string Hil() { return BinDir() + "/hil"; }
std::string Vector(const std::string& name) { return GpsdVector(name); }

// The bytes the devices produced with their emulated times, one line per byte: emulated time,
// message name, byte. tx and drop lines alike (in real time a byte nobody could take at its time
// is captured as a drop, and a message can be split between the two: issue 15.7); the wall-clock
// columns and record boundaries are left out.
std::string TxLines(const std::string& capture) {
  std::string out, line;
  std::istringstream in(capture);
  while (std::getline(in, line)) {
    if (line.rfind("tx ", 0) != 0 && line.rfind("drop ", 0) != 0) continue;
    std::istringstream fields(line);
    std::string kind, name, hex;
    long long t_emu = 0, period = 0, wall = 0;
    fields >> kind >> t_emu >> period >> wall >> name >> hex;
    for (std::size_t k = 0; k + 1 < hex.size(); k += 2) {
      out += std::to_string(t_emu + period * static_cast<long long>(k / 2)) + " " + name + " " +
             hex.substr(k, 2) + "\n";
    }
  }
  return out;
}

bool ProcessWithArgsExists(const std::string& a0, const std::string& a1) {
  DIR* d = opendir("/proc");
  bool found = false;
  while (dirent* e = readdir(d)) {
    if (!std::isdigit(static_cast<unsigned char>(e->d_name[0]))) continue;
    const std::string cmd = ReadFile(std::string("/proc/") + e->d_name + "/cmdline");
    if (cmd == a0 + '\0' + a1 + '\0') found = true;
  }
  closedir(d);
  return found;
}

TEST(HilValidateE2eTest, RealReceiverCapturesConformAndBrokenOnesDoNot) {
  HIL_SKIP_WITHOUT_GPSD_VECTORS();
  TempDir dir("e2e_validate");
  for (const char* log : {"ublox-lea-5h.log", "nl551e.log", "nl402u.log", "ublox-lea-5q.log"}) {
    const CommandResult r = RunCommand(Hil() + " validate --protocol neo5m " + Vector(log));
    EXPECT_EQ(r.exit_code, 0) << log << "\n" << r.out;
    EXPECT_NE(r.out.find("CONFORMS"), std::string::npos);
  }
  CommandResult r = RunCommand(Hil() + " validate --protocol ubx " + Vector("navisys-gr701w.log") +
                               " --report " + dir / "ubx.json");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const auto rep = nlohmann::json::parse(ReadFile(dir / "ubx.json"));
  EXPECT_TRUE(rep["conforms"].get<bool>());
  EXPECT_EQ(rep["frames"].get<int>(), 423);
  // one flipped bit in a copy of a real capture
  std::string text = ReadFile(Vector("nl402u.log"));
  const std::size_t at = text.find("$GPGGA") + 20;
  text[at] = static_cast<char>(text[at] ^ 0x01);
  WriteFile(dir / "broken.log", text);
  r = RunCommand(Hil() + " validate --protocol nmea " + dir / "broken.log");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("checksum mismatch"), std::string::npos) << r.out;
  // bad input
  EXPECT_EQ(RunCommand(Hil() + " validate --protocol nmea " + dir / "missing.log").exit_code, 2);
  EXPECT_EQ(RunCommand(Hil() + " validate --protocol morse " + Vector("nl402u.log")).exit_code, 2);
}

TEST(HilRunModesE2eTest, BytesIdenticalInVirtualScaledAndRealtimeModes) {
  TempDir dir("e2e_modes");
  WriteFile(dir / "s.yaml", "name: modes\nduration_s: 6\nseed: 5\n" + kOrigin);
  const std::string s = dir / "s.yaml";
  CommandResult r = RunCommand(Hil() + " run " + s + " --out " + dir / "v");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = RunCommand(Hil() + " run " + s + " --mode scaled --speed 20 --out " + dir / "sc");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = RunCommand(Hil() + " run " + s + " --mode realtime --speed 12 --out " + dir / "rt");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string v = TxLines(ReadFile(dir / "v/captures/ttyGPS.cap"));
  ASSERT_GT(v.size(), 1000u);
  EXPECT_EQ(v, TxLines(ReadFile(dir / "sc/captures/ttyGPS.cap")));
  EXPECT_EQ(v, TxLines(ReadFile(dir / "rt/captures/ttyGPS.cap")));
  const auto sc = nlohmann::json::parse(ReadFile(dir / "sc/report.json"));
  EXPECT_EQ(sc["mode"], "scaled");
  EXPECT_TRUE(sc["metrics"]["latency_ms"].is_object()) << "latency is measured in scaled mode";
  EXPECT_TRUE(
      nlohmann::json::parse(ReadFile(dir / "v/report.json"))["metrics"]["latency_ms"].is_null());
  // scaled needs a speed
  EXPECT_EQ(RunCommand(Hil() + " run " + s + " --mode scaled --out " + dir / "x").exit_code, 2);
  // virtual mode has no free-running form
  const CommandResult fr = RunCommand(Hil() + " run " + s + " --free-running --out " + dir / "y");
  EXPECT_EQ(fr.exit_code, 2);
  EXPECT_NE(fr.out.find("--free-running needs --mode realtime or scaled"), std::string::npos)
      << fr.out;
}

// In real time a UART sends whether anyone listens: the clock starts once the estimator has opened
// its links, so a slow start (here 0.8 s, 16 emulated seconds at 20x) loses no epoch.
TEST(HilRunModesE2eTest, ScaledRunStartsWhenTheEstimatorHasOpenedItsLinks) {
  TempDir dir("e2e_slow_start");
  WriteFile(dir / "s.yaml", "name: slow\nduration_s: 6\nseed: 5\n" + kOrigin);
  const CommandResult r = RunCommand(Hil() + " run " + dir / "s.yaml" +
                                     " --mode scaled --speed 20 --out " + dir / "sc" +
                                     " --estimator 'sleep 0.8; exec {navd} --config "
                                     "{run_dir}/navd.conf'");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto rep = nlohmann::json::parse(ReadFile(dir / "sc/report.json"));
  EXPECT_GE(rep["host_open_wait_s"].get<double>(), 0.8);
  EXPECT_EQ(rep["metrics"]["samples"].get<int>(), 6) << r.out;
  EXPECT_EQ(rep["metrics"]["solutions_missing_fraction"].get<double>(), 0.0);
}

TEST(HilRunEstimatorE2eTest, HungEstimatorIsDetectedReportedAndStopped) {
  TempDir dir("e2e_hang");
  WriteFile(dir / "s.yaml", "name: hang\nduration_s: 200\n" + kOrigin);
  for (const char* mode : {"virtual", "scaled --speed 50"}) {
    const std::string out = dir / (std::string("run_") + mode[0]);
    const CommandResult r =
        RunCommand(Hil() + " run " + dir / "s.yaml" + " --mode " + mode + " --out " + out +
                   " --estimator 'exec sleep 987' --silence-timeout 1");
    EXPECT_EQ(r.exit_code, 1) << mode << "\n" << r.out;
    const auto report = nlohmann::json::parse(ReadFile(out + "/report.json"));
    EXPECT_FALSE(report["pass"].get<bool>());
    EXPECT_FALSE(report["complete"].get<bool>());
    const std::string problems = report["problems"].dump();
    EXPECT_NE(problems.find("the estimator hung"), std::string::npos) << r.out;
    if (std::string(mode) != "virtual") {
      EXPECT_NE(problems.find("had not opened every link it reads"), std::string::npos) << r.out;
    }
    EXPECT_LT(report["wall_time_s"].get<double>(), 30.0) << "detected in about the silence timeout";
    EXPECT_FALSE(ProcessWithArgsExists("sleep", "987")) << "the estimator is always stopped";
  }
}

TEST(HilRunEstimatorE2eTest, NmeaOutputOnStdoutAndOnAPty) {
  TempDir dir("e2e_nmea_out");
  // `cat` of the receiver's own NMEA is an "estimator" whose solutions are the raw fixes
  WriteFile(dir / "stdout.yaml",
            "name: nmea_stdout\nduration_s: 20\n" + kOrigin +
                "estimator: {command: 'cat {ttyGPS}', output: nmea_stdout}\n"
                "criteria:\n  - {metric: horizontal_rmse_m, max_ratio_to_baseline: 1.01}\n");
  WriteFile(dir / "pty.yaml",
            "name: nmea_pty\nduration_s: 20\n" + kOrigin +
                "estimator: {command: 'cat {ttyGPS} > {ttyNAV}', output: nmea_pty}\n"
                "criteria:\n  - {metric: output_rate_hz, min: 0.99}\n");
  for (const char* s : {"stdout", "pty"}) {
    const CommandResult r =
        RunCommand(Hil() + " run " + dir / (std::string(s) + ".yaml") + " --out " + dir / s);
    EXPECT_EQ(r.exit_code, 0) << s << "\n" << r.out;
    const auto report = nlohmann::json::parse(ReadFile(dir / (std::string(s) + "/report.json")));
    EXPECT_GE(report["metrics"]["samples"].get<int>(), 20) << s;
    // the same fixes, rounded to NMEA's 1e-5 arc-minute (≤ 1 cm): the RMSE agrees to a few
    // millimetres
    EXPECT_NEAR(report["metrics"]["horizontal_rmse_m"].get<double>(),
                report["baselines"]["horizontal_rmse_m"].get<double>(), 5e-3)
        << s << ": the solutions are the fixes (NMEA rounding only)";
  }
}

TEST(HilRunEstimatorE2eTest, GpsdIsAnEstimatorUnderTest) {
  // gpsd reads the emulated receiver; its TPV reports are the solutions (gpsd moves dates before
  // its build's GPS week window by 1024 weeks, so this scenario lives in 2025)
  TempDir dir("e2e_gpsd");
  const std::string port = std::to_string(20000 + ::getpid() % 20000);
  WriteFile(dir / "s.yaml",
            "name: gpsd\nduration_s: 15\nstart_utc: \"2025-06-10T08:00:00Z\"\n" + kOrigin +
                "estimator:\n  command: \"gpsd -N -n -b -S " + port +
                " -F {run_dir}/gpsd.sock {ttyGPS} & "
                "sleep 0.5; exec gpspipe -w localhost:" +
                port +
                "\"\n  output: gpsd_json\n  startup_s: 1\n"
                "criteria:\n  - {metric: horizontal_rmse_m, max_ratio_to_baseline: 1.01}\n");
  const CommandResult r = RunCommand(Hil() + " run " + dir / "s.yaml" + " --out " + dir / "run");
  EXPECT_EQ(r.exit_code, 0) << r.out << ReadFile(dir / "run/estimator.stderr");
  const auto report = nlohmann::json::parse(ReadFile(dir / "run/report.json"));
  EXPECT_GE(report["metrics"]["samples"].get<int>(), 15);
}

TEST(HilRunEstimatorE2eTest, NavdConfiguresAStockReceiverWithUbxCfg) {
  // the emulated NEO-5M starts with its default NMEA output; navd switches it to UBX navigation at
  // 4 Hz with CFG commands over the pty and waits for each ACK, as a production driver does. A
  // command/answer session depends on the host's reaction time, so it runs on the wall clock
  // (scaled ×2): a virtual run would see the host answer only when it catches up with the emulation
  TempDir dir("e2e_cfg");
  WriteFile(
      dir / "s.yaml",
      "name: cfg\nduration_s: 20\n" + kOrigin +
          "estimator:\n  navd_input: {gnss_protocol: ubx, gnss_configure: true, gnss_rate_hz: 4}\n"
          // the rate is measured over the evaluated window: the first seconds are the
          // configuration dialogue, at the receiver's default 1 Hz
          "evaluation: {from_s: 5}\n"
          "criteria:\n  - {metric: output_rate_hz, min: 3.9}\n");
  const CommandResult r = RunCommand(Hil() + " run " + dir / "s.yaml" +
                                     " --mode scaled --speed 2 --out " + dir / "run");
  const std::string stderr_text = ReadFile(dir / "run/estimator.stderr");
  EXPECT_EQ(r.exit_code, 0) << r.out << stderr_text;
  EXPECT_NE(stderr_text.find("11 commands: 11 acked, 0 refused, 0 unanswered"), std::string::npos)
      << stderr_text;
  EXPECT_NE(ReadFile(dir / "run/navd.conf").find("gnss_configure = true"), std::string::npos);
  // the capture holds both directions: navd's commands, the receiver's ACKs, then UBX only
  const std::string cap = ReadFile(dir / "run/captures/ttyGPS.cap");
  std::istringstream in(cap);
  std::string line;
  int rx = 0, acks = 0, posllh_late = 0, nmea_late = 0;
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string dir_field, t_emu, period, wall, name;
    f >> dir_field >> t_emu >> period >> wall >> name;
    if (dir_field == "rx") ++rx;
    if (dir_field != "tx") continue;
    const bool late = std::stoll(t_emu) > 10'000'000'000LL;
    acks += name == "UBX-ACK-ACK" ? 1 : 0;
    posllh_late += late && name == "UBX-NAV-POSLLH" ? 1 : 0;
    nmea_late += late && name.rfind("NMEA-", 0) == 0 ? 1 : 0;
  }
  EXPECT_GE(rx, 1) << "host-to-receiver bytes are captured";
  EXPECT_EQ(acks, 11);
  EXPECT_NEAR(posllh_late, 40, 1) << "NAV-POSLLH at 4 Hz in the last 10 s";
  EXPECT_EQ(nmea_late, 0) << "NMEA switched off";
  const auto report = nlohmann::json::parse(ReadFile(dir / "run/report.json"));
  EXPECT_NEAR(report["metrics"]["output_rate_hz"].get<double>(), 4.0, 0.1);
}

TEST(HilRunFaultsE2eTest, OutagesAreEvaluatedAndByteCorruptionReachesTheCapture) {
  TempDir dir("e2e_faults");
  WriteFile(dir / "s.yaml", "name: faults\nduration_s: 40\n" + kOrigin +
                                "faults:\n"
                                "  - {kind: gnss_outage, start_s: 10, end_s: 15}\n"
                                "  - {kind: byte_corruption, start_s: 20, end_s: 30, probability: "
                                "0.002, link: ttyGPS}\n");
  const CommandResult r = RunCommand(Hil() + " run " + dir / "s.yaml" + " --out " + dir / "run");
  ASSERT_NE(r.exit_code, 2) << r.out;
  const auto report = nlohmann::json::parse(ReadFile(dir / "run/report.json"));
  const auto& outages = report["metrics"]["outages"];
  ASSERT_EQ(outages.size(), 1u);
  EXPECT_DOUBLE_EQ(outages[0]["start_s"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(outages[0]["end_s"].get<double>(), 15.0);
  EXPECT_TRUE(outages[0].contains("max_horizontal_error_m"));
  EXPECT_TRUE(outages[0].contains("reconvergence_time_s"));
  EXPECT_GT(report["fault_effects"]["bytes_corrupted"].get<int>(), 0);
  // the corrupted bytes are what the link carried: the capture no longer conforms
  const CommandResult v =
      RunCommand(Hil() + " validate --protocol nmea " + dir / "run/captures/ttyGPS.cap");
  EXPECT_EQ(v.exit_code, 1) << v.out;
  EXPECT_NE(v.out.find("checksum"), std::string::npos) << v.out;
  EXPECT_NE(ReadFile(dir / "run/report.html").find("GNSS outages"), std::string::npos);
}

TEST(HilReportE2eTest, ReportHtmlIsASelfContainedSignoffDocument) {
  TempDir dir("e2e_html");
  WriteFile(dir / "s.yaml", "name: html\nduration_s: 15\n" + kOrigin);
  const CommandResult r = RunCommand(Hil() + " run " + dir / "s.yaml" + " --out " + dir / "run");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string html = ReadFile(dir / "run/report.html");
  ASSERT_FALSE(html.empty());
  // one file: the charts inline, nothing fetched when it is viewed
  EXPECT_EQ(html.find("<img"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  const std::regex svg("<svg xmlns=");
  const auto charts =
      std::distance(std::sregex_iterator(html.begin(), html.end(), svg), std::sregex_iterator());
  EXPECT_EQ(charts, 6) << "map, worst segment, cross-track, error against time, NEES, error CDF";
  EXPECT_NE(html.find("the latency chart does not apply"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "run/plots/latency_histogram.svg"));
  // the header is true: the scenario file's SHA-256, the site (ellipsoidal height), the seed
  const CommandResult sha = RunCommand("sha256sum " + dir / "s.yaml");
  ASSERT_EQ(sha.exit_code, 0);
  EXPECT_NE(html.find("<code>" + sha.out.substr(0, 64) + "</code>"), std::string::npos);
  EXPECT_NE(html.find("35.4796096&deg; N, 50.5979765&deg; E, height 1312.00 m above the WGS-84 "
                      "ellipsoid"),
            std::string::npos);
  EXPECT_NE(html.find("<td>gnss_receiver</td><td>ttyGPS</td><td>profile neo-5m"),
            std::string::npos);
  EXPECT_NE(html.find("<th>seed</th><td>1</td>"), std::string::npos);
  EXPECT_NE(html.find("PASS"), std::string::npos);
  EXPECT_NE(ReadFile(dir / "run/plots/trajectory.svg").find("<polyline"), std::string::npos);
}

TEST(HilSuiteE2eTest, SuiteRunsEveryScenarioIntoOneSummary) {
  TempDir dir("e2e_suite");
  std::filesystem::create_directories(dir / "mixed");
  std::filesystem::create_directories(dir / "good");
  std::filesystem::create_directories(dir / "empty");
  WriteFile(dir / "mixed/a_pass.yaml", "name: a_pass\nduration_s: 8\n" + kOrigin);
  WriteFile(dir / "mixed/b_fail.yaml",
            "name: b_fail\nduration_s: 8\n" + kOrigin +
                "criteria:\n  - {metric: horizontal_rmse_m, max: 0.0001}\n");
  WriteFile(dir / "good/a.yaml", "name: a\nduration_s: 8\n" + kOrigin);
  CommandResult r =
      RunCommand(Hil() + " suite " + dir / "mixed" + " -j 2 --out " + dir / "out_mixed");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  auto summary = nlohmann::json::parse(ReadFile(dir / "out_mixed/summary.json"));
  EXPECT_EQ(summary["runs"].size(), 2u);
  EXPECT_EQ(summary["passed"].get<int>(), 1);
  EXPECT_EQ(summary["failed"].get<int>(), 1);
  const std::string junit = ReadFile(dir / "out_mixed/junit.xml");
  EXPECT_NE(junit.find("<testsuite name=\"a_pass\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("<failure"), std::string::npos);

  r = RunCommand(Hil() + " suite " + dir / "good" + " --repeat 3 --seed 11 -j 2 --out " +
                 dir / "out_good");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  summary = nlohmann::json::parse(ReadFile(dir / "out_good/summary.json"));
  ASSERT_EQ(summary["runs"].size(), 3u);
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(summary["runs"][static_cast<std::size_t>(i)]["seed"].get<int>(), 11 + i);
  EXPECT_TRUE(std::filesystem::exists(dir / "out_good/runs/a-seed13/report.json"));

  EXPECT_EQ(RunCommand(Hil() + " suite " + dir / "empty" + " --out " + dir / "out_empty").exit_code,
            2);
  EXPECT_EQ(RunCommand(Hil() + " suite " + dir / "nowhere").exit_code, 2);
}

}  // namespace
}  // namespace hil::test

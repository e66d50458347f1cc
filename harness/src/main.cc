// hil — the hardware-in-the-loop harness CLI.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "hil/harness/replay.h"
#include "hil/harness/run.h"
#include "hil/harness/yaml_reader.h"

namespace {

namespace fs = std::filesystem;

std::string SiblingExecutable(const std::string& name) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path candidate = self.parent_path() / name;
    if (fs::exists(candidate)) return candidate.string();
  }
  return name;  // rely on PATH
}

void PrintSummary(const hil::harness::RunReport& r, const std::string& dir) {
  const auto fmt = [](const hil::harness::AccuracyMetrics& m, double v) {
    char b[32];
    if (m.samples == 0) return std::string("n/a");
    std::snprintf(b, sizeof b, "%.3f m", v);
    return std::string(b);
  };
  std::printf("scenario   %s (seed %llu, %s mode, %.0f s simulated in %.2f s)\n", r.scenario.c_str(),
              static_cast<unsigned long long>(r.seed), r.mode.c_str(), r.sim_time_s, r.wall_time_s);
  std::printf("estimate   horizontal RMSE %s, CEP95 %s, max %s (%zu solutions, %.2f Hz)\n",
              fmt(r.metrics, r.metrics.horizontal_rmse_m).c_str(), fmt(r.metrics, r.metrics.cep95_m).c_str(),
              fmt(r.metrics, r.metrics.max_horizontal_error_m).c_str(), r.metrics.samples, r.output_rate_hz);
  std::printf("raw GNSS   horizontal RMSE %s, CEP95 %s, max %s (%zu fixes)\n",
              fmt(r.baselines, r.baselines.horizontal_rmse_m).c_str(), fmt(r.baselines, r.baselines.cep95_m).c_str(),
              fmt(r.baselines, r.baselines.max_horizontal_error_m).c_str(), r.baselines.samples);
  for (const auto& c : r.criteria) {
    std::printf("  [%s] %s (value %s)\n", c.pass ? "PASS" : "FAIL", c.name.c_str(),
                c.value ? std::to_string(*c.value).c_str() : "n/a");
  }
  for (const auto& p : r.problems) std::printf("  [FAIL] %s\n", p.c_str());
  std::printf("%s  report: %s/report.json\n", r.pass() ? "PASS" : "FAIL", dir.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hil — hardware-in-the-loop test harness for agricultural-robot navigation"};
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  hil run                              run the embedded default scenario into runs/<name>\n"
      "  hil run my_field.yaml --out out/a    run a scenario file\n"
      "  hil run --mode realtime --seed 7     bytes at their wall-clock UART times\n"
      "  hil replay runs/x/captures/ttyGPS.cap   replay a capture into runs/replay/ttyGPS\n"
      "Exit codes: 0 every criterion passed, 1 a criterion failed, 2 bad input.");

  std::string scenario_path, out_dir, mode = "virtual", estimator_cmd;
  std::uint64_t seed = 0;
  double speed = 1.0;
  auto* run = app.add_subcommand("run", "Run a scenario end to end and evaluate the estimator");
  run->add_option("SCENARIO", scenario_path, "scenario file (YAML); omitted: the embedded default scenario");
  run->add_option("--out", out_dir, "run folder (default: runs/<scenario name>)");
  auto* seed_opt = run->add_option("--seed", seed, "random seed (overrides the scenario's)");
  run->add_option("--mode", mode, "virtual (as fast as possible) or realtime")->check(CLI::IsMember({"virtual", "realtime"}));
  run->add_option("--speed", speed, "real-time speed-up factor (realtime mode)")->check(CLI::Range(0.01, 1000.0));
  auto* est_opt = run->add_option("--estimator", estimator_cmd,
                                  "estimator command ({navd}, {run_dir}, {seed}, {ttyGPS} are substituted)");

  std::string emu_scenario, emu_out;
  double emu_speed = 1.0;
  auto* emulate = app.add_subcommand("emulate",
                                     "Run the device emulators alone in real time; attach gpsd, ubxtool or your own "
                                     "program to the printed links (e.g. DIR/ttyGPS)");
  emulate->add_option("SCENARIO", emu_scenario, "scenario file (YAML); omitted: the embedded default scenario");
  emulate->add_option("--out", emu_out, "run folder holding the links and captures (default: runs/<name>-emulate)");
  emulate->add_option("--speed", emu_speed, "speed-up factor")->check(CLI::Range(0.01, 1000.0));

  // hil replay (links): captures back into ptys / onto CAN at their recorded byte times
  hil::harness::ReplayOptions replay_opt;
  replay_opt.out_dir = "runs/replay";
  auto* replay = app.add_subcommand("replay",
                                    "Play captures (RUN/captures/*.cap, candump -l logs) back at their recorded "
                                    "timing: serial bytes into ptys OUT/<link>, CAN frames onto an interface");
  replay->add_option("CAPTURE", replay_opt.captures, "capture files and candump logs, played together")->required();
  replay->add_option("--out", replay_opt.out_dir, "folder for the pty links and the re-capture (default runs/replay)");
  replay->add_option("--speed", replay_opt.speed, "speed-up factor")->check(CLI::Range(0.01, 1000.0));
  replay->add_option("--delay", replay_opt.start_delay_s, "seconds between creating the links and the first byte (default 1)")
      ->check(CLI::Range(0.0, 3600.0));
  replay->add_option("--can-iface", replay_opt.can_iface, "play every CAN source onto this interface (default: as recorded)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "hil: %s (see hil --help)\n", e.what());
    return 2;
  }

  if (replay->parsed()) {
    replay_opt.on_links = [](const std::vector<std::pair<std::string, std::string>>& links) {
      for (const auto& [name, path] : links) std::printf("%s %s\n", name.c_str(), path.c_str());
      std::fflush(stdout);
    };
    try {
      const hil::harness::ReplayResult r = hil::harness::ReplayCaptures(replay_opt);
      std::printf("replayed %llu bytes and %llu CAN frames (%llu refused); re-capture in %s/captures\n",
                  static_cast<unsigned long long>(r.bytes), static_cast<unsigned long long>(r.frames),
                  static_cast<unsigned long long>(r.frames_failed), replay_opt.out_dir.c_str());
      return r.frames_failed == 0 ? 0 : 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "hil: %s\n", e.what());
      return 2;
    }
  }
  if (emulate->parsed()) {
    hil::harness::Scenario scenario;
    try {
      scenario = emu_scenario.empty() ? hil::harness::LoadDefaultScenario() : hil::harness::LoadScenario(emu_scenario);
    } catch (const hil::harness::ScenarioError& e) {
      std::fprintf(stderr, "hil: invalid scenario: %s\n", e.what());
      return 2;
    }
    hil::harness::RunOptions opt;
    opt.out_dir = emu_out.empty() ? "runs/" + scenario.name + "-emulate" : emu_out;
    opt.mode = hil::harness::RunMode::kRealtime;
    opt.speed = emu_speed;
    opt.emulate_only = true;
    try {
      hil::harness::RunScenario(scenario, opt);
      return 0;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "hil: %s\n", e.what());
      return 2;
    }
  }
  if (run->parsed()) {
    hil::harness::Scenario scenario;
    try {
      scenario = scenario_path.empty() ? hil::harness::LoadDefaultScenario() : hil::harness::LoadScenario(scenario_path);
    } catch (const hil::harness::ScenarioError& e) {
      std::fprintf(stderr, "hil: invalid scenario: %s\n", e.what());
      return 2;
    }
    hil::harness::RunOptions opt;
    opt.out_dir = out_dir.empty() ? "runs/" + scenario.name : out_dir;
    if (*seed_opt) opt.seed = seed;
    opt.mode = mode == "realtime" ? hil::harness::RunMode::kRealtime : hil::harness::RunMode::kVirtual;
    opt.speed = speed;
    if (*est_opt) opt.estimator_command = estimator_cmd;
    opt.navd_path = SiblingExecutable("navd");
    opt.progress = isatty(STDERR_FILENO);
    try {
      const hil::harness::RunReport report = hil::harness::RunScenario(scenario, opt);
      PrintSummary(report, opt.out_dir);
      return report.pass() ? 0 : 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "hil: %s\n", e.what());
      return 2;
    }
  }
  return 2;
}

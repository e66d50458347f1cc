// hil — the hardware-in-the-loop harness CLI. Each subcommand has its options struct, a function
// that declares them and a function that runs it; main() only parses and dispatches.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "hil/harness/replay/replay.h"
#include "hil/harness/run/run.h"
#include "hil/harness/scenario/yaml_reader.h"
#include "hil/harness/suite/suite.h"
#include "hil/harness/validate/validate.h"
#include "hil/harness/validate/validate_can_live.h"

namespace {

namespace fs = std::filesystem;
using hil::harness::RunMode;

constexpr int kExitPass = 0, kExitFail = 1, kExitBadInput = 2;

std::string SelfExecutable() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? "hil" : self.string();
}

std::string SiblingExecutable(const std::string& name) {
  const fs::path candidate = fs::path(SelfExecutable()).parent_path() / name;
  std::error_code ec;
  return fs::exists(candidate, ec) ? candidate.string() : name;  // else rely on PATH
}

void PrintSummary(const hil::harness::RunReport& r, const std::string& dir) {
  const auto fmt = [](const hil::harness::AccuracyMetrics& m, double v) {
    char b[32];
    if (m.samples == 0) return std::string("n/a");
    std::snprintf(b, sizeof b, "%.3f m", v);
    return std::string(b);
  };
  std::printf("scenario   %s (seed %llu, %s mode, %.0f s simulated in %.2f s, %.0fx real time)\n",
              r.scenario.c_str(), static_cast<unsigned long long>(r.seed), r.mode.c_str(),
              r.sim_time_s, r.wall_time_s, r.wall_time_s > 0 ? r.sim_time_s / r.wall_time_s : 0.0);
  std::printf("estimate   horizontal RMSE %s, CEP95 %s, max %s (%zu solutions, %.2f Hz)\n",
              fmt(r.metrics, r.metrics.horizontal_rmse_m).c_str(),
              fmt(r.metrics, r.metrics.cep95_m).c_str(),
              fmt(r.metrics, r.metrics.max_horizontal_error_m).c_str(), r.metrics.samples,
              r.output_rate_hz);
  std::printf("raw GNSS   horizontal RMSE %s, CEP95 %s, max %s (%zu fixes)\n",
              fmt(r.baselines, r.baselines.horizontal_rmse_m).c_str(),
              fmt(r.baselines, r.baselines.cep95_m).c_str(),
              fmt(r.baselines, r.baselines.max_horizontal_error_m).c_str(), r.baselines.samples);
  for (const auto& o : r.outages) {
    char reconv[64] = "never";
    if (o.reconvergence_time_s)
      std::snprintf(reconv, sizeof reconv, "%.1f s after", *o.reconvergence_time_s);
    std::printf("outage     %.1f-%.1f s: max horizontal error %s, reconverged %s\n", o.start_s,
                o.end_s,
                o.samples ? (std::to_string(o.max_horizontal_error_m).substr(0, 5) + " m").c_str()
                          : "n/a (no solutions)",
                reconv);
  }
  for (const auto& c : r.criteria) {
    std::printf("  [%s] %s (value %s)\n", c.pass ? "PASS" : "FAIL", c.name.c_str(),
                c.value ? std::to_string(*c.value).c_str() : "n/a");
  }
  for (const auto& p : r.problems) std::printf("  [FAIL] %s\n", p.c_str());
  std::printf("%s  report: %s/report.html\n", r.pass() ? "PASS" : "FAIL", dir.c_str());
}

std::optional<hil::harness::Scenario> LoadOrReport(const std::string& path,
                                                   bool short_form = false) {
  try {
    return path.empty() ? hil::harness::LoadDefaultScenario()
                        : hil::harness::LoadScenario(path, short_form);
  } catch (const hil::harness::ScenarioError& e) {
    std::fprintf(stderr, "hil: invalid scenario: %s\n", e.what());
    return std::nullopt;
  }
}

// ---------------------------------------------------------------- hil run
struct RunArgs {
  CLI::App* cmd = nullptr;
  std::string scenario, out, mode = "virtual", estimator;
  std::uint64_t seed = 0;
  double speed = 1.0, silence_timeout_s = 0;
  CLI::Option *seed_opt = nullptr, *est_opt = nullptr, *speed_opt = nullptr, *silence_opt = nullptr;
  bool no_html = false, short_form = false;
};

void AddRun(CLI::App& app, RunArgs& a) {
  a.cmd = app.add_subcommand("run", "Run a scenario end to end and evaluate the estimator");
  a.cmd->add_option("SCENARIO", a.scenario,
                    "scenario file (YAML); omitted: the embedded default scenario");
  a.cmd->add_option("--out", a.out, "run folder (default: runs/<scenario name>)");
  a.seed_opt = a.cmd->add_option("--seed", a.seed, "random seed (overrides the scenario's)");
  a.cmd
      ->add_option("--mode", a.mode,
                   "virtual (as fast as possible), realtime (bytes at their wall-clock UART times) "
                   "or scaled "
                   "(real time sped up by --speed); the bytes are the same in every mode")
      ->check(CLI::IsMember({"virtual", "realtime", "scaled"}));
  a.speed_opt = a.cmd->add_option("--speed", a.speed, "speed-up factor of realtime/scaled mode")
                    ->check(CLI::Range(0.01, 1000.0));
  a.est_opt = a.cmd->add_option(
      "--estimator", a.estimator,
      "estimator command ({navd}, {run_dir}, {seed}, {ttyGPS}, {ttyNAV} are substituted)");
  a.silence_opt =
      a.cmd
          ->add_option(
              "--silence-timeout", a.silence_timeout_s,
              "seconds without estimator output that count as a hang (overrides the scenario)")
          ->check(CLI::Range(0.1, 3600.0));
  a.cmd->add_flag("--no-html", a.no_html, "skip report.html and the plots");
  a.cmd->add_flag("--short", a.short_form,
                  "the scenario's quick form: its `short:` keys replace the top-level ones");
}

int Run(const RunArgs& a) {
  const auto scenario = LoadOrReport(a.scenario, a.short_form);
  if (!scenario) return kExitBadInput;
  if (a.mode == "scaled" && !*a.speed_opt) {
    std::fprintf(stderr, "hil: --mode scaled needs --speed (see hil run --help)\n");
    return kExitBadInput;
  }
  hil::harness::RunOptions opt;
  opt.out_dir = a.out.empty() ? "runs/" + scenario->name : a.out;
  if (*a.seed_opt) opt.seed = a.seed;
  opt.mode = a.mode == "virtual" ? RunMode::kVirtual : RunMode::kRealtime;
  opt.speed = a.speed;
  if (*a.est_opt) opt.estimator_command = a.estimator;
  if (*a.silence_opt) opt.silence_timeout_s = a.silence_timeout_s;
  opt.navd_path = SiblingExecutable("navd");
  opt.progress = isatty(STDERR_FILENO);
  opt.html = !a.no_html;
  try {
    const hil::harness::RunReport report = hil::harness::RunScenario(*scenario, opt);
    PrintSummary(report, opt.out_dir);
    return report.pass() ? kExitPass : kExitFail;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

// ---------------------------------------------------------------- hil emulate
struct EmulateArgs {
  CLI::App* cmd = nullptr;
  std::string scenario, out;
  double speed = 1.0;
};

void AddEmulate(CLI::App& app, EmulateArgs& a) {
  a.cmd = app.add_subcommand(
      "emulate",
      "Run the device emulators alone in real time; attach gpsd, ubxtool or your own "
      "program to the printed links (e.g. DIR/ttyGPS)");
  a.cmd->add_option("SCENARIO", a.scenario,
                    "scenario file (YAML); omitted: the embedded default scenario");
  a.cmd->add_option("--out", a.out,
                    "run folder holding the links and captures (default: runs/<name>-emulate)");
  a.cmd->add_option("--speed", a.speed, "speed-up factor")->check(CLI::Range(0.01, 1000.0));
}

int Emulate(const EmulateArgs& a) {
  const auto scenario = LoadOrReport(a.scenario);
  if (!scenario) return kExitBadInput;
  hil::harness::RunOptions opt;
  opt.out_dir = a.out.empty() ? "runs/" + scenario->name + "-emulate" : a.out;
  opt.mode = RunMode::kRealtime;
  opt.speed = a.speed;
  opt.emulate_only = true;
  opt.html = false;
  try {
    hil::harness::RunScenario(*scenario, opt);
    return kExitPass;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

// ---------------------------------------------------------------- hil validate
struct ValidateArgs {
  CLI::App* cmd = nullptr;
  std::string protocol, source, report;
  int baud = 9600;
  double listen_s = 10.0;
  bool quiet = false;
};

void AddValidate(CLI::App& app, ValidateArgs& a) {
  a.cmd = app.add_subcommand(
      "validate",
      "Check a device's stream for conformance: framing, checksums, message set and rates "
      "against the profile, epoch timing, sequence gaps. Exit 0 conforms, 1 does not, 2 bad input");
  a.cmd
      ->add_option("--protocol", a.protocol,
                   "ubx, nmea, neo5m (NMEA and UBX against the u-blox 5 profile), mcu (MCU frame "
                   "protocol v1) or can "
                   "(candump -l log, or a live interface such as vcan0)")
      ->required()
      ->check(CLI::IsMember({"ubx", "nmea", "neo5m", "mcu", "can"}));
  a.cmd
      ->add_option("SOURCE", a.source,
                   "a hil capture (captures/*.cap), a raw log (gpsd .log), a candump -l log, or a "
                   "serial device "
                   "(e.g. /dev/ttyUSB0, RUN_DIR/ttyGPS)")
      ->required();
  a.cmd
      ->add_option("--baud", a.baud,
                   "line rate of a serial device, and the neo5m per-epoch byte budget")
      ->check(CLI::Range(300, 921600));
  a.cmd->add_option("--listen", a.listen_s, "seconds to listen to a serial device or CAN interface")
      ->check(CLI::Range(0.1, 86400.0));
  a.cmd->add_option("--report", a.report, "write the conformance report as JSON to this file");
  a.cmd->add_flag("--quiet", a.quiet, "print only the verdict line");
}

int Validate(const ValidateArgs& a) {
  using hil::harness::ValidateProtocol;
  hil::harness::ValidationReport rep;
  try {
    if (a.protocol == "can" && hil::harness::IsNetworkInterface(a.source)) {
      rep = hil::harness::ValidateCanInterface(a.source, a.listen_s);
    } else if (a.protocol == "can") {
      const hil::harness::ByteStream s = hil::harness::ReadByteSource(a.source, a.listen_s, a.baud);
      rep = hil::harness::ValidateCanLog(s.bytes);
    } else if (a.protocol == "mcu") {
      rep = hil::harness::ValidateMcuStream(
          hil::harness::ReadByteSource(a.source, a.listen_s, a.baud));
    } else {
      const ValidateProtocol p = a.protocol == "ubx"    ? ValidateProtocol::kUbx
                                 : a.protocol == "nmea" ? ValidateProtocol::kNmea
                                                        : ValidateProtocol::kNeo5m;
      rep = hil::harness::ValidateStream(
          p, hil::harness::ReadByteSource(a.source, a.listen_s, a.baud), a.baud);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
  rep.source = a.source;
  if (a.quiet) {
    std::printf("%s: %s\n", a.source.c_str(), rep.conforms() ? "CONFORMS" : "DOES NOT CONFORM");
  } else {
    std::fputs(hil::harness::ValidationSummary(rep).c_str(), stdout);
  }
  if (!a.report.empty()) {
    try {
      hil::harness::WriteValidationJson(rep, a.report);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "hil: %s\n", e.what());
      return kExitBadInput;
    }
  }
  return rep.conforms() ? kExitPass : kExitFail;
}

// ---------------------------------------------------------------- hil suite
struct SuiteArgs {
  CLI::App* cmd = nullptr;
  std::string dir, out, estimator, mode;
  int jobs = 2, repeat = 1;
  std::uint64_t seed = 1;
  double speed = 1.0;
  bool short_form = false;
  CLI::Option *seed_opt = nullptr, *est_opt = nullptr, *mode_opt = nullptr, *speed_opt = nullptr;
};

void AddSuite(CLI::App& app, SuiteArgs& a) {
  a.cmd = app.add_subcommand(
      "suite",
      "Run every scenario of a folder (in parallel, optionally with several seeds) into one "
      "report.md (the papers' figures beside ours), summary.json and junit.xml; exit 0 when all "
      "pass");
  a.cmd->add_option("DIR", a.dir, "folder of scenario files (*.yaml)")->required();
  a.cmd->add_option("--out", a.out, "suite folder (default: runs/suite-<DIR name>)");
  a.cmd->add_option("-j,--jobs", a.jobs, "scenarios run at the same time")
      ->check(CLI::Range(1, 64));
  a.cmd
      ->add_option(
          "--seeds,--repeat", a.repeat,
          "runs of each scenario, with seeds SEED, SEED+1, … (mean and spread in the report)")
      ->check(CLI::Range(1, 1000));
  a.cmd->add_flag("--short", a.short_form,
                  "each scenario's quick form (its `short:` section: shorter runs, for CI); "
                  "scenarios without one run whole");
  a.seed_opt = a.cmd->add_option("--seed", a.seed,
                                 "first seed (default: each scenario's own, or 1 with --seeds)");
  a.est_opt = a.cmd->add_option("--estimator", a.estimator, "estimator command for every run");
  a.mode_opt = a.cmd->add_option("--mode", a.mode, "run mode for every run")
                   ->check(CLI::IsMember({"virtual", "realtime", "scaled"}));
  a.speed_opt = a.cmd->add_option("--speed", a.speed, "speed-up factor for realtime/scaled runs")
                    ->check(CLI::Range(0.01, 1000.0));
}

int Suite(const SuiteArgs& a) {
  hil::harness::SuiteOptions opt;
  opt.dir = a.dir;
  opt.out_dir = a.out.empty()
                    ? "runs/suite-" + fs::path(a.dir).lexically_normal().filename().string()
                    : a.out;
  opt.hil_exe = SelfExecutable();
  opt.jobs = a.jobs;
  opt.repeat = a.repeat;
  if (*a.seed_opt) opt.seed = a.seed;
  if (*a.est_opt) opt.run_args.insert(opt.run_args.end(), {"--estimator", a.estimator});
  if (*a.mode_opt) opt.run_args.insert(opt.run_args.end(), {"--mode", a.mode});
  if (*a.speed_opt) opt.run_args.insert(opt.run_args.end(), {"--speed", std::to_string(a.speed)});
  opt.short_form = a.short_form;
  opt.run_args.emplace_back("--no-html");
  try {
    if (hil::harness::SuiteScenarios(a.dir).empty()) {
      std::fprintf(stderr, "hil: no scenario files (*.yaml) in %s\n", a.dir.c_str());
      return kExitBadInput;
    }
    const hil::harness::SuiteResult r = hil::harness::RunSuite(opt);
    std::printf(
        "%s  %zu run(s): %zu passed, %zu failed, %zu invalid  report: %s/report.md, summary.json, "
        "junit.xml\n",
        r.exit_code() == 0 ? "PASS" : "FAIL", r.runs, r.passed, r.failed, r.invalid,
        opt.out_dir.c_str());
    return r.exit_code();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hil — hardware-in-the-loop test harness for agricultural-robot navigation"};
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  hil run                                  run the embedded default scenario into "
      "runs/<name>\n"
      "  hil run my_field.yaml --out out/a        run a scenario file\n"
      "  hil run --mode scaled --speed 10         bytes at their UART times, 10x faster than real "
      "time\n"
      "  hil validate --protocol neo5m runs/x/captures/ttyGPS.cap\n"
      "  hil suite vectors/scenarios -j 2 --seeds 3     papers' figures beside ours: "
      "runs/suite-scenarios/report.md\n"
      "  hil replay runs/x/captures/ttyGPS.cap      replay a capture into runs/replay/ttyGPS\n"
      "Exit codes: 0 every criterion passed (validate: conforms), 1 one failed, 2 bad input.");
  RunArgs run;
  EmulateArgs emulate;
  ValidateArgs validate;
  SuiteArgs suite;
  AddRun(app, run);
  AddEmulate(app, emulate);
  AddValidate(app, validate);
  AddSuite(app, suite);

  // hil replay (links): captures back into ptys / onto CAN at their recorded byte times
  hil::harness::ReplayOptions replay_opt;
  replay_opt.out_dir = "runs/replay";
  auto* replay = app.add_subcommand(
      "replay",
      "Play captures (RUN/captures/*.cap, candump -l logs) back at their recorded "
      "timing: serial bytes into ptys OUT/<link>, CAN frames onto an interface");
  replay
      ->add_option("CAPTURE", replay_opt.captures,
                   "capture files and candump logs, played together")
      ->required();
  replay->add_option("--out", replay_opt.out_dir,
                     "folder for the pty links and the re-capture (default runs/replay)");
  replay->add_option("--speed", replay_opt.speed, "speed-up factor")
      ->check(CLI::Range(0.01, 1000.0));
  replay
      ->add_option("--delay", replay_opt.start_delay_s,
                   "seconds between creating the links and the first byte (default 1)")
      ->check(CLI::Range(0.0, 3600.0));
  replay->add_option("--can-iface", replay_opt.can_iface,
                     "play every CAN source onto this interface (default: as recorded)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "hil: %s (see hil --help)\n", e.what());
    return kExitBadInput;
  }

  if (replay->parsed()) {
    replay_opt.on_links = [](const std::vector<std::pair<std::string, std::string>>& links) {
      for (const auto& [name, path] : links) std::printf("%s %s\n", name.c_str(), path.c_str());
      std::fflush(stdout);
    };
    try {
      const hil::harness::ReplayResult r = hil::harness::ReplayCaptures(replay_opt);
      std::printf(
          "replayed %llu bytes and %llu CAN frames (%llu refused); re-capture in %s/captures\n",
          static_cast<unsigned long long>(r.bytes), static_cast<unsigned long long>(r.frames),
          static_cast<unsigned long long>(r.frames_failed), replay_opt.out_dir.c_str());
      return r.frames_failed == 0 ? 0 : 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "hil: %s\n", e.what());
      return 2;
    }
  }
  if (run.cmd->parsed()) return Run(run);
  if (emulate.cmd->parsed()) return Emulate(emulate);
  if (validate.cmd->parsed()) return Validate(validate);
  if (suite.cmd->parsed()) return Suite(suite);
  return kExitBadInput;
}

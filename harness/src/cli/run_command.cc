// hil run: one scenario end to end, its summary on stdout.
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "hil/harness/cli/commands.h"
#include "hil/harness/report/output_file.h"
#include "hil/harness/run/run.h"

namespace hil::cli {
namespace {

using harness::RunMode;

// The fused estimate's errors as fractions of the raw fixes' (below 1: the fusion does better),
// when both were scored.
void PrintFusedVsRaw(const hil::harness::RunReport& r) {
  const auto& e = r.metrics;
  const auto& g = r.baselines;
  if (e.samples == 0 || g.samples == 0 || g.horizontal_rmse_m <= 0 || g.cep95_m <= 0 ||
      g.max_horizontal_error_m <= 0)
    return;
  std::printf(
      "fused/raw  horizontal RMSE %.2fx, CEP95 %.2fx, max %.2fx (below 1: better than the raw "
      "fixes)\n",
      e.horizontal_rmse_m / g.horizontal_rmse_m, e.cep95_m / g.cep95_m,
      e.max_horizontal_error_m / g.max_horizontal_error_m);
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
  PrintFusedVsRaw(r);
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
  for (const auto& d : r.default_criteria) {
    if (d.status != "judged" && d.status != "relaxed" && d.status != "tightened")
      std::printf("  [----] default %s: %s (%s)\n", d.key.c_str(), d.status.c_str(),
                  d.detail.c_str());
  }
  for (const auto& p : r.problems) std::printf("  [FAIL] %s\n", p.c_str());
  std::printf("%s  report: %s/report.html\n", r.pass() ? "PASS" : "FAIL", dir.c_str());
}

// A run folder not all written, then an interrupted run, come before the verdict: neither is a
// run that failed its criteria.
int RunExitCode(const hil::harness::RunReport& r) {
  if (!r.write_failure.empty()) {
    std::fprintf(stderr, "hil: %s (the run's outputs are not all written)\n",
                 r.write_failure.c_str());
    return kExitWriteFailure;
  }
  if (r.interrupt_signal != 0) return kExitInterruptedBase + r.interrupt_signal;
  return r.pass() ? kExitPass : kExitFail;
}

struct RunArgs {
  CLI::App* cmd = nullptr;
  std::string scenario, out, mode = "virtual", estimator;
  std::uint64_t seed = 0;
  double speed = 1.0, silence_timeout_s = 0;
  int nice = harness::kDefaultRunNice;
  CLI::Option *seed_opt = nullptr, *est_opt = nullptr, *speed_opt = nullptr, *silence_opt = nullptr;
  bool no_html = false, short_form = false, free_running = false, lockstep = false,
       no_lookahead = false;
  std::vector<std::string> sets;
};

void Declare(CLI::App& app, RunArgs& a) {
  a.cmd = app.add_subcommand("run", "Run a scenario end to end and evaluate the estimator");
  a.cmd->add_option("SCENARIO", a.scenario,
                    "scenario file (YAML); omitted: the embedded default scenario");
  a.cmd->add_option("--out", a.out,
                    "run folder (default: runs/<scenario name>-seed<N>, with -2, -3, ... added "
                    "when it exists)");
  a.seed_opt = a.cmd->add_option("--seed", a.seed, "random seed (overrides the scenario's)")
                   ->check(SeedValidator());
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
  a.cmd->add_flag("--free-running", a.free_running,
                  "realtime/scaled closed loop without lockstep: bytes leave at their UART times "
                  "and commands act when they arrive (runs then differ); by default a closed "
                  "loop runs lockstep, as in virtual mode, each step held to its wall-clock time");
  a.cmd
      ->add_option("--nice", a.nice,
                   "nice value of hil and the processes it starts (every wake-up of a hand-over "
                   "gets the CPU at once on a busy machine); 0 leaves it, a refusal is reported")
      ->capture_default_str()
      ->check(CLI::Range(-20, 19));
  a.cmd->add_flag("--lockstep", a.lockstep,
                  "virtual mode: the estimator and controller run on the emulated clock through "
                  "libhil_lockstep.so (preloaded; their clocks, sleeps, poll/select/epoll and "
                  "blocking reads follow emulated time), not paced by probing /proc");
  a.cmd->add_flag("--no-lookahead", a.no_lookahead,
                  "with --lockstep: a host turn per message even where the programs hold their "
                  "links read-only (open loop), instead of writing ahead (the same bytes, slower)");
  a.cmd->add_flag("--short", a.short_form,
                  "the scenario's quick form: its `short:` keys replace the top-level ones");
  a.cmd->add_option("--set", a.sets,
                    "FIELD=VALUE: set one scenario field (dotted path, [i] for list elements, a "
                    "YAML value), e.g. --set gnss.baud=38400; repeatable");
}

int Execute(const RunArgs& a) {
  std::vector<harness::ScenarioOverride> overrides;
  try {
    for (const auto& text : a.sets) overrides.push_back(harness::ParseOverride(text));
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "hil: --set: %s\n", e.what());
    return kExitBadInput;
  }
  const auto scenario = LoadOrReport(a.scenario, a.short_form, overrides);
  if (!scenario) return kExitBadInput;
  if (a.mode == "scaled" && !*a.speed_opt) {
    std::fprintf(stderr, "hil: --mode scaled needs --speed (see hil run --help)\n");
    return kExitBadInput;
  }
  if (a.mode != "virtual" && a.lockstep) {
    std::fprintf(stderr, "hil: --lockstep needs --mode virtual (see hil run --help)\n");
    return kExitBadInput;
  }
  if (a.mode == "virtual" && a.free_running) {
    std::fprintf(stderr,
                 "hil: --free-running needs --mode realtime or scaled (see hil run --help)\n");
    return kExitBadInput;
  }
  hil::harness::RunOptions opt;
  if (*a.seed_opt) opt.seed = a.seed;
  opt.mode = a.mode == "virtual" ? RunMode::kVirtual : RunMode::kRealtime;
  opt.speed = a.speed;
  if (*a.est_opt) opt.estimator_command = a.estimator;
  if (*a.silence_opt) opt.silence_timeout_s = a.silence_timeout_s;
  opt.navd_path = SiblingExecutable("navd");
  opt.guidanced_path = SiblingExecutable("guidanced");
  opt.progress = isatty(STDERR_FILENO);
  opt.html = !a.no_html;
  opt.free_running = a.free_running;
  opt.lockstep = a.lockstep;
  opt.lockstep_lookahead = !a.no_lookahead;
  opt.nice = a.nice;
  try {
    opt.out_dir =
        a.out.empty() ? DefaultRunFolder(scenario->name, opt.seed.value_or(scenario->seed)) : a.out;
    const hil::harness::RunReport report = hil::harness::RunScenario(*scenario, opt);
    PrintSummary(report, opt.out_dir);
    return RunExitCode(report);
  } catch (const harness::OutputWriteError& e) {
    std::fprintf(stderr, "hil: %s (the run's outputs are not all written)\n", e.what());
    return kExitWriteFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace

Subcommand AddRun(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  Declare(app, *a);
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli

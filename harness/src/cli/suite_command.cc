// hil suite: every scenario of a folder, N seeds each, into one report.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "hil/harness/cli/commands.h"
#include "hil/harness/suite/suite.h"

namespace hil::cli {
namespace {

namespace fs = std::filesystem;

struct SuiteArgs {
  CLI::App* cmd = nullptr;
  std::string dir, out, estimator, mode;
  int jobs = 2, repeat = 1, nice = 0;
  std::uint64_t seed = 1;
  double speed = 1.0;
  bool short_form = false;
  CLI::Option *seed_opt = nullptr, *est_opt = nullptr, *mode_opt = nullptr, *speed_opt = nullptr,
              *nice_opt = nullptr;
};

void Declare(CLI::App& app, SuiteArgs& a) {
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
  a.seed_opt = a.cmd
                   ->add_option("--seed", a.seed,
                                "first seed (default: each scenario's own, or 1 with --seeds)")
                   ->check(SeedValidator());
  a.est_opt = a.cmd->add_option("--estimator", a.estimator, "estimator command for every run");
  a.mode_opt = a.cmd->add_option("--mode", a.mode, "run mode for every run")
                   ->check(CLI::IsMember({"virtual", "realtime", "scaled"}));
  a.speed_opt = a.cmd->add_option("--speed", a.speed, "speed-up factor for realtime/scaled runs")
                    ->check(CLI::Range(0.01, 1000.0));
  a.nice_opt = a.cmd
                   ->add_option("--nice", a.nice,
                                "nice value of every run (hil run --nice; default: hil run's "
                                "-10); 0 leaves the priority as it is")
                   ->check(CLI::Range(-20, 19));
}

int Execute(const SuiteArgs& a) {
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
  if (*a.nice_opt) opt.run_args.insert(opt.run_args.end(), {"--nice", std::to_string(a.nice)});
  opt.short_form = a.short_form;
  try {
    if (hil::harness::SuiteScenarios(a.dir).empty()) {
      std::fprintf(stderr, "hil: no scenario files (*.yaml) in %s\n", a.dir.c_str());
      return kExitBadInput;
    }
    const hil::harness::SuiteResult r = hil::harness::RunSuite(opt);
    std::printf(
        "%s  %zu run(s): %zu passed, %zu failed, %zu invalid; %zu criteria across seeds failed  "
        "report: %s/report.md, summary.json, junit.xml\n",
        r.exit_code() == 0 ? "PASS" : "FAIL", r.runs, r.passed, r.failed, r.invalid,
        r.criteria_failed, opt.out_dir.c_str());
    return r.exit_code();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace

Subcommand AddSuite(CLI::App& app) {
  auto a = std::make_shared<SuiteArgs>();
  Declare(app, *a);
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli

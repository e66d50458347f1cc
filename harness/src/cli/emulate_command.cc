// hil emulate: the device emulators alone, in real time.
#include <cstdio>
#include <memory>

#include "hil/harness/cli/commands.h"
#include "hil/harness/run/run.h"

namespace hil::cli {
namespace {

using harness::RunMode;

struct EmulateArgs {
  CLI::App* cmd = nullptr;
  std::string scenario, out;
  double speed = 1.0;
  int nice = harness::kDefaultRunNice;
};

void Declare(CLI::App& app, EmulateArgs& a) {
  a.cmd = app.add_subcommand(
      "emulate",
      "Run the device emulators alone in real time; attach gpsd, ubxtool or your own "
      "program to the printed links (e.g. DIR/ttyGPS)");
  a.cmd->add_option("SCENARIO", a.scenario,
                    "scenario file (YAML); omitted: the embedded default scenario");
  a.cmd->add_option("--out", a.out,
                    "run folder holding the links and captures (default: runs/<name>-emulate)");
  a.cmd->add_option("--speed", a.speed, "speed-up factor")->check(CLI::Range(0.01, 1000.0));
  a.cmd
      ->add_option("--nice", a.nice,
                   "nice value of hil; below 0 its pacing threads also ask for SCHED_FIFO, 0 or "
                   "more leaves them at SCHED_OTHER (0 leaves the priority as it is)")
      ->capture_default_str()
      ->check(CLI::Range(-20, 19));
}

int Execute(const EmulateArgs& a) {
  const auto scenario = LoadOrReport(a.scenario);
  if (!scenario) return kExitBadInput;
  hil::harness::RunOptions opt;
  opt.out_dir = a.out.empty() ? "runs/" + scenario->name + "-emulate" : a.out;
  opt.mode = RunMode::kRealtime;
  opt.speed = a.speed;
  opt.emulate_only = true;
  opt.html = false;
  opt.nice = a.nice;
  try {
    hil::harness::RunScenario(*scenario, opt);
    return kExitPass;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace

Subcommand AddEmulate(CLI::App& app) {
  auto a = std::make_shared<EmulateArgs>();
  Declare(app, *a);
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli

// hil replay: captures back into ptys / onto CAN at their recorded byte times.
#include <cstdio>
#include <memory>

#include "hil/harness/cli/commands.h"
#include "hil/harness/replay/replay.h"

namespace hil::cli {
namespace {

struct ReplayArgs {
  CLI::App* cmd = nullptr;
  harness::ReplayOptions opt;
};

void Declare(CLI::App& app, ReplayArgs& a) {
  harness::ReplayOptions& opt = a.opt;
  opt.out_dir = "runs/replay";
  a.cmd = app.add_subcommand("replay",
                             "Play captures (RUN/captures/*.cap, candump -l logs) back at their "
                             "recorded timing: serial bytes into ptys OUT/<link>, CAN frames "
                             "onto an interface");
  a.cmd->add_option("CAPTURE", opt.captures, "capture files and candump logs, played together")
      ->required();
  a.cmd->add_option("--out", opt.out_dir,
                    "folder for the pty links and the re-capture (default runs/replay)");
  a.cmd->add_option("--speed", opt.speed, "speed-up factor")->check(CLI::Range(0.01, 1000.0));
  a.cmd
      ->add_option("--delay", opt.start_delay_s,
                   "seconds between creating the links and the first byte (default 1)")
      ->check(CLI::Range(0.0, 3600.0));
  a.cmd->add_option("--can-iface", opt.can_iface,
                    "play every CAN source onto this interface (default: as recorded)");
}

int Execute(ReplayArgs& a) {
  a.opt.on_links = [](const std::vector<std::pair<std::string, std::string>>& links) {
    for (const auto& [name, path] : links) std::printf("%s %s\n", name.c_str(), path.c_str());
    std::fflush(stdout);
  };
  try {
    const harness::ReplayResult r = harness::ReplayCaptures(a.opt);
    std::printf(
        "replayed %llu bytes and %llu CAN frames (%llu refused); re-capture in %s/captures\n",
        static_cast<unsigned long long>(r.bytes), static_cast<unsigned long long>(r.frames),
        static_cast<unsigned long long>(r.frames_failed), a.opt.out_dir.c_str());
    return r.frames_failed == 0 ? kExitPass : kExitFail;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace

Subcommand AddReplay(CLI::App& app) {
  auto a = std::make_shared<ReplayArgs>();
  Declare(app, *a);
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli

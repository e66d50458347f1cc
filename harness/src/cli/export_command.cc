// hil export: a run's emulated IMU, GNSS fixes and truth in KF-GINS's or gnss-ins-sim's formats.
#include <cstdio>
#include <memory>

#include "hil/harness/cli/commands.h"
#include "hil/harness/datasets/run_export.h"

namespace hil::cli {
namespace {

struct ExportArgs {
  CLI::App* cmd = nullptr;
  std::string run, format = "kfgins", dir;
};

int Execute(const ExportArgs& a) {
  try {
    const harness::RunExportResult r = harness::ExportRun(a.run, a.format, a.dir);
    std::printf(
        "exported %s as %s into %s: %llu IMU, %llu GNSS, %llu truth lines (%llu bad "
        "frames skipped)\n",
        a.run.c_str(), a.format.c_str(), a.dir.c_str(),
        static_cast<unsigned long long>(r.imu_lines), static_cast<unsigned long long>(r.gnss_lines),
        static_cast<unsigned long long>(r.truth_lines),
        static_cast<unsigned long long>(r.bad_frames));
    return kExitPass;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace

Subcommand AddExport(CLI::App& app) {
  auto a = std::make_shared<ExportArgs>();
  a->cmd = app.add_subcommand("export",
                              "Write a run's IMU (as the device measured it), GNSS fixes and truth "
                              "in KF-GINS's text formats or gnss-ins-sim's CSV layout");
  a->cmd->add_option("RUN", a->run, "run folder (report.json, captures/, truth.csv, ...)")
      ->required();
  a->cmd->add_option("--format", a->format, "kfgins (default) or gnss-ins-sim")
      ->check(CLI::IsMember({"kfgins", "gnss-ins-sim"}));
  a->cmd->add_option("DIR", a->dir, "output folder")->required();
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli

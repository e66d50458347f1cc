// hil — the hardware-in-the-loop harness CLI. Each subcommand lives in harness/src/cli/ (its
// options and how it runs); main() only parses and dispatches.
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include "hil/harness/cli/commands.h"

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
      "  hil campaign mc.yaml --local -j 2          scenarios x seeds x sweeps, merged report\n"
      "  hil campaign mc.yaml --slurm --wait        the same as a Slurm job array\n"
      "  hil characterize runs/x/captures/ttyIMU.cap --json n.json --svg plots   Allan, PSD\n"
      "  hil scenario-keys                          every scenario key: type, unit, default, "
      "range\n"
      "Exit codes: 0 every criterion passed (validate: conforms), 1 one failed, 2 bad input.");
  const std::vector<hil::cli::Subcommand> commands{
      hil::cli::AddRun(app),         hil::cli::AddEmulate(app),  hil::cli::AddValidate(app),
      hil::cli::AddSuite(app),       hil::cli::AddReplay(app),   hil::cli::AddDataset(app),
      hil::cli::AddExport(app),      hil::cli::AddCampaign(app), hil::cli::AddCharacterize(app),
      hil::cli::AddScenarioKeys(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "hil: %s (see hil --help)\n", e.what());
    return hil::cli::kExitBadInput;
  }
  for (const hil::cli::Subcommand& c : commands) {
    if (c.cmd->parsed()) return c.run();
  }
  return hil::cli::kExitBadInput;
}

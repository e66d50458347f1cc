// hil scenario-keys: the scenario reference, generated from the tables the reader validates with
// (scenario_keys.h); docs/scenario_reference.md is its output.
#include <cstdio>
#include <memory>

#include "hil/harness/cli/commands.h"
#include "hil/harness/devices/scenario_file.h"

namespace hil::cli {

Subcommand AddScenarioKeys(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "scenario-keys",
      "Print the scenario reference (Markdown): every key of every section with its type, unit, "
      "default, allowed range and meaning, from the reader's own tables "
      "(docs/scenario_reference.md)");
  auto markdown = std::make_shared<bool>(true);
  cmd->add_flag("--markdown", *markdown, "Markdown (the only format; the default)");
  return {cmd, [] {
            const std::string text = harness::ScenarioReference();
            return std::fwrite(text.data(), 1, text.size(), stdout) == text.size()
                       ? kExitPass
                       : kExitWriteFailure;
          }};
}

}  // namespace hil::cli

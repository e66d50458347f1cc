// What the subcommands share: finding executables and loading a scenario.
#include <cstdio>
#include <filesystem>

#include "hil/harness/cli/commands.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::cli {

namespace fs = std::filesystem;

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

std::optional<harness::Scenario> LoadOrReport(
    const std::string& path, bool short_form,
    const std::vector<harness::ScenarioOverride>& overrides) {
  try {
    if (path.empty() && !overrides.empty()) {
      std::fprintf(stderr, "hil: --set needs a scenario file\n");
      return std::nullopt;
    }
    return path.empty() ? hil::harness::LoadDefaultScenario()
                        : hil::harness::LoadScenario(path, short_form, overrides);
  } catch (const hil::harness::ScenarioError& e) {
    std::fprintf(stderr, "hil: invalid scenario: %s\n", e.what());
    return std::nullopt;
  }
}

}  // namespace hil::cli

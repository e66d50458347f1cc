// What the subcommands share: finding executables and loading a scenario.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <sys/stat.h>

#include "hil/harness/cli/commands.h"
#include "hil/harness/devices/scenario_file.h"
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

std::string DefaultRunFolder(const std::string& scenario_name, std::uint64_t seed) {
  std::string name;
  for (const char c : scenario_name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '-' || c == '_' || c == '.' || c == '+';
    name += plain ? c : '_';
  }
  if (name.empty() || name.find_first_not_of('.') == std::string::npos) name = "_" + name;
  const std::string base = "runs/" + name + "-seed" + std::to_string(seed);
  std::error_code ec;
  fs::create_directories("runs", ec);
  // mkdir claims the folder: two runs started at once never get the same one
  for (int k = 1; k <= kMaxRunFolderSuffix; ++k) {
    const std::string dir = k == 1 ? base : base + "-" + std::to_string(k);
    if (mkdir(dir.c_str(), 0755) == 0) return dir;
    if (errno != EEXIST) break;
  }
  throw std::runtime_error("cannot make a new run folder " + base + "[-N] (" +
                           std::to_string(kMaxRunFolderSuffix) +
                           " taken, or runs/ is not writable): give one with --out");
}

CLI::Validator SeedValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string range = "a seed is a whole number from 0 to " +
                                  std::to_string(harness::kMaxSeed) +
                                  ", as a scenario's seed key holds";
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
          return "'" + text + "' is not a seed (" + range + ")";
        errno = 0;
        const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
        if (errno == ERANGE || v > static_cast<unsigned long long>(harness::kMaxSeed))
          return text + " is out of range (" + range + ")";
        return "";
      },
      "SEED");
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

#pragma once
// A test process's own folders under the system's temporary directory: named by a tag and the
// process id (tests of one build run side by side), emptied when first asked for and removed when
// the process exits, so a test run leaves nothing behind in /tmp, whatever the tests' outcome.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace hil::test {

/// `<tmp>/hil_<tag>_<pid>`, created (empty the first time it is asked for in this process) and
/// removed, with all it holds, at the process's exit.
inline std::filesystem::path ProcessTempDir(const std::string& tag) {
  struct Registry {
    std::vector<std::filesystem::path> dirs;
    ~Registry() {
      std::error_code ec;
      for (const auto& d : dirs) std::filesystem::remove_all(d, ec);
    }
  };
  static Registry registry;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("hil_" + tag + "_" + std::to_string(::getpid()));
  if (std::find(registry.dirs.begin(), registry.dirs.end(), dir) == registry.dirs.end()) {
    std::filesystem::remove_all(dir);
    registry.dirs.push_back(dir);
  }
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace hil::test

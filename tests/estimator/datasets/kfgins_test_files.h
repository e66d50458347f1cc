#pragma once
// Small files for the dataset reader tests: written into a fresh temporary folder.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace hil::estimator::datasets::testing {

inline std::string TempDir() {
  char tmpl[] = "/tmp/kfgins_test_XXXXXX";
  const char* d = mkdtemp(tmpl);
  return d ? std::string(d) : std::string("/tmp");
}

/// A temporary folder removed with everything in it at the end of the scope.
struct ScopedTempDir {
  std::string path = TempDir();
  ~ScopedTempDir() { std::filesystem::remove_all(path); }
};

inline std::string WriteFile(const std::string& dir, const std::string& name,
                             const std::string& text) {
  const std::string path = dir + "/" + name;
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fputs(text.c_str(), f);
  std::fclose(f);
  return path;
}

}  // namespace hil::estimator::datasets::testing

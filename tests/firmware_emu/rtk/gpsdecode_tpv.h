#pragma once
// gpsd's gpsdecode (3.22, Debian package gpsd-clients) as a judge: the TPV reports it prints for
// a byte stream (gpsdecode -j), shared by the gpsd judge tests of the ZED-F9P rover.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hil::rtk::test {

inline constexpr const char* kGpsdecode = "/usr/bin/gpsdecode";

inline bool GpsdecodeInstalled() { return access(kGpsdecode, X_OK) == 0; }

/// gpsdecode -j over `bytes` (through a temporary file named with `tag`); its TPV reports.
inline std::vector<nlohmann::json> GpsdecodeTpv(const std::string& bytes, const std::string& tag) {
  namespace fs = std::filesystem;
  const fs::path file = fs::temp_directory_path() / ("zed_f9p_" + tag + std::to_string(getpid()));
  std::ofstream(file, std::ios::binary) << bytes;
  std::vector<nlohmann::json> tpv;
  FILE* p = popen((std::string(kGpsdecode) + " -j < " + file.string()).c_str(), "r");
  std::string line;
  for (int c = 0; p != nullptr && (c = fgetc(p)) != EOF;) {
    if (c != '\n') {
      line.push_back(static_cast<char>(c));
      continue;
    }
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_discarded() && j.value("class", "") == "TPV") tpv.push_back(j);
    line.clear();
  }
  if (p != nullptr) pclose(p);
  fs::remove(file);
  return tpv;
}

}  // namespace hil::rtk::test

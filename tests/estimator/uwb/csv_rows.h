#pragma once
// Reads a vectors/ CSV (comment lines start with '#', one header line) into rows of fields.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hil::estimator::uwb::test {

inline std::string VectorPath(const std::string& rel) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/" + rel;
}

inline std::vector<std::vector<std::string>> ReadCsvRows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) f.push_back(cell);
    rows.push_back(f);
  }
  return rows;
}

}  // namespace hil::estimator::uwb::test

#pragma once
// Reads the project's vectors/ files from tests: a path below the source tree ($HIL_SOURCE_DIR),
// a binary file whole, and a CSV (comment lines start with '#', one header line) as rows of fields.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hil::test {

inline std::string VectorPath(const std::string& rel) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/" + rel;
}

inline std::string ReadVectorBytes(const std::string& rel) {
  std::ifstream f(VectorPath(rel), std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
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

/// A vectors/ CSV of numbers only, as rows of doubles.
inline std::vector<std::vector<double>> ReadCsvNumbers(const std::string& rel) {
  std::vector<std::vector<double>> rows;
  for (const auto& fields : ReadCsvRows(VectorPath(rel))) {
    std::vector<double> r;
    r.reserve(fields.size());
    for (const std::string& c : fields) r.push_back(std::stod(c));
    rows.push_back(r);
  }
  return rows;
}

}  // namespace hil::test

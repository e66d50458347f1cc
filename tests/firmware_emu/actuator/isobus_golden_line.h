#pragma once
// One line of vectors/isobus/guidance_golden.txt: "<id>#<hex> key=value ...".

#include <array>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace hil::test {

struct IsobusGoldenLine {
  int line_number = 0;
  std::uint32_t id = 0;
  std::uint8_t len = 0;
  std::array<std::uint8_t, 8> data{};
  std::map<std::string, std::string> fields;
  double Num(const std::string& key) const { return std::strtod(fields.at(key).c_str(), nullptr); }
  int Int(const std::string& key) const {
    return static_cast<int>(std::strtol(fields.at(key).c_str(), nullptr, 0));
  }
};

inline std::vector<IsobusGoldenLine> ReadIsobusGolden(const std::string& path) {
  std::ifstream in(path);
  std::vector<IsobusGoldenLine> out;
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string frame;
    words >> frame;
    IsobusGoldenLine g;
    g.line_number = n;
    const auto hash = frame.find('#');
    g.id = static_cast<std::uint32_t>(std::stoul(frame.substr(0, hash), nullptr, 16));
    const std::string hex = frame.substr(hash + 1);
    g.len = static_cast<std::uint8_t>(hex.size() / 2);
    for (std::size_t i = 0; i < g.len && i < 8; ++i)
      g.data[i] = static_cast<std::uint8_t>(std::stoul(hex.substr(2 * i, 2), nullptr, 16));
    for (std::string kv; words >> kv;) {
      const auto eq = kv.find('=');
      g.fields[kv.substr(0, eq)] = kv.substr(eq + 1);
    }
    out.push_back(g);
  }
  return out;
}

inline std::string IsobusGoldenPath() {
  const char* dir = std::getenv("HIL_SOURCE_DIR");
  return std::string(dir ? dir : ".") + "/vectors/isobus/guidance_golden.txt";
}

}  // namespace hil::test

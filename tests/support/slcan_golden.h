#pragma once
// Reads vectors/slcan/slcan_golden.txt (vectors/slcan/README.md) for the SLCAN tests of both
// sides: frame lines (record, candump frame, check), bad records, and the session's exchanges.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "vector_files.h"

namespace hil::test {

struct SlcanGoldenFrame {
  std::string record;  ///< without CR
  std::uint32_t id = 0;
  bool extended = false, rtr = false;
  std::vector<std::uint8_t> data;
  std::string check;  ///< "both" or "decode"
};

struct SlcanGoldenBad {
  std::string record, error;
};

struct SlcanGoldenExchange {
  std::string host, reply;  ///< unescaped (\r, \a); reply "" for `-`
};

struct SlcanGolden {
  std::vector<SlcanGoldenFrame> frames;
  std::vector<SlcanGoldenBad> bad;
  std::vector<SlcanGoldenExchange> session;
};

inline std::string SlcanUnescape(const std::string& s) {
  if (s == "-") return "";
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      const char c = s[++i];
      out.push_back(c == 'r' ? '\r' : c == 'a' ? '\a' : c == 'n' ? '\n' : c);
    } else {
      out.push_back(s[i]);
    }
  }
  return out;
}

// "0CAD1C80#807DFD" / "123#R" / "123#"
inline SlcanGoldenFrame SlcanParseCandump(const std::string& record, const std::string& cd) {
  SlcanGoldenFrame f;
  f.record = record;
  const std::size_t hash = cd.find('#');
  const std::string id = cd.substr(0, hash), data = cd.substr(hash + 1);
  f.id = static_cast<std::uint32_t>(std::stoul(id, nullptr, 16));
  f.extended = id.size() == 8;
  f.rtr = data == "R";
  if (!f.rtr) {
    for (std::size_t i = 0; i + 1 < data.size(); i += 2)
      f.data.push_back(static_cast<std::uint8_t>(std::stoul(data.substr(i, 2), nullptr, 16)));
  }
  return f;
}

inline SlcanGolden ReadSlcanGolden() {
  SlcanGolden g;
  std::ifstream in(VectorPath("vectors/slcan/slcan_golden.txt"));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream w(line);
    std::string kind, a, b, c;
    w >> kind >> a >> b;
    if (kind == "frame") {
      w >> c;
      SlcanGoldenFrame f = SlcanParseCandump(a, b);
      f.check = c.substr(c.find('=') + 1);
      g.frames.push_back(f);
    } else if (kind == "bad") {
      g.bad.push_back({a, b.substr(b.find('=') + 1)});
    } else if (kind == "host") {
      w >> c;  // b is "reply"
      g.session.push_back({SlcanUnescape(a), SlcanUnescape(c)});
    }
  }
  return g;
}

}  // namespace hil::test

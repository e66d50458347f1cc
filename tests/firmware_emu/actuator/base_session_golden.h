#pragma once
// vectors/base_serial/session_golden.tsv: time_ms, host bytes, reply bytes (C escapes).

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace hil::test {

struct BaseExchange {
  int line_number = 0;
  std::int64_t t_ms = 0;
  std::string host;
  std::string reply;
};

inline std::string Unescape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      const char c = s[++i];
      out.push_back(c == 'r' ? '\r' : c == 'n' ? '\n' : c);
    } else {
      out.push_back(s[i]);
    }
  }
  return out;
}

inline std::vector<BaseExchange> ReadBaseSessionGolden() {
  const char* dir = std::getenv("HIL_SOURCE_DIR");
  std::ifstream in(std::string(dir ? dir : ".") + "/vectors/base_serial/session_golden.tsv");
  std::vector<BaseExchange> out;
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    const auto a = line.find('\t');
    const auto b = line.find('\t', a + 1);
    BaseExchange e;
    e.line_number = n;
    e.t_ms = std::stoll(line.substr(0, a));
    e.host = Unescape(line.substr(a + 1, b - a - 1));
    e.reply = Unescape(line.substr(b + 1));
    out.push_back(e);
  }
  return out;
}

}  // namespace hil::test

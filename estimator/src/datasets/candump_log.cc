#include "hil/estimator/datasets/candump_log.h"

#include <charconv>
#include <fstream>

namespace hil::estimator::datasets {
namespace {

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// the next blank-separated word of `s` from `pos`
std::string_view Word(std::string_view s, std::size_t& pos) {
  while (pos < s.size() && (s[pos] == ' ' || s[pos] == '\t')) ++pos;
  const std::size_t start = pos;
  while (pos < s.size() && s[pos] != ' ' && s[pos] != '\t') ++pos;
  return s.substr(start, pos - start);
}

// "(SECONDS.FRACTION)" → ns; false when malformed
bool ParseTimestamp(std::string_view w, std::int64_t& ns) {
  if (w.size() < 4 || w.front() != '(' || w.back() != ')') return false;
  w = w.substr(1, w.size() - 2);
  const std::size_t dot = w.find('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 >= w.size() || w.size() - dot > 10)
    return false;
  std::int64_t s = 0, frac = 0;
  const char* end = w.data() + dot;
  if (std::from_chars(w.data(), end, s).ptr != end) return false;
  const std::string_view f = w.substr(dot + 1);
  if (std::from_chars(f.data(), f.data() + f.size(), frac).ptr != f.data() + f.size() || frac < 0)
    return false;
  for (std::size_t i = f.size(); i < 9; ++i) frac *= 10;
  ns = s * 1000000000LL + frac;
  return true;
}

// "ID#DATA" / "ID#R[n]" / "ID#DATA_D" into `r`; throws naming the field
void ParseFrame(std::string_view w, CandumpRecord& r, const auto& fail) {
  const std::size_t hash = w.find('#');
  if (hash == std::string_view::npos) fail("frame: no '#' between identifier and data");
  if (hash + 1 < w.size() && w[hash + 1] == '#')
    fail("frame: CAN FD frame (##) not supported; the J1939 IMU frames are classic CAN");
  if (hash != 3 && hash != 8) fail("identifier: 3 (11-bit) or 8 (29-bit) hex digits expected");
  std::uint32_t id = 0;
  for (std::size_t i = 0; i < hash; ++i) {
    const int d = HexDigit(w[i]);
    if (d < 0) fail("identifier: not hex");
    id = id << 4 | static_cast<std::uint32_t>(d);
  }
  r.frame.extended = hash == 8;
  if (id > (r.frame.extended ? 0x1FFFFFFFu : 0x7FFu)) fail("identifier: out of range");
  r.frame.id = id;
  std::string_view data = w.substr(hash + 1);
  if (!data.empty() && (data[0] == 'R' || data[0] == 'r')) {
    r.remote = true;
    if (data.size() > 2 || (data.size() == 2 && (data[1] < '0' || data[1] > '8')))
      fail("remote frame: length digit 0-8 expected after R");
    r.frame.len = data.size() == 2 ? static_cast<std::uint8_t>(data[1] - '0') : 0;
    return;
  }
  if (const std::size_t u = data.find('_'); u != std::string_view::npos) {
    if (u + 2 != data.size() || HexDigit(data[u + 1]) < 0) fail("data: bad length code after '_'");
    data = data.substr(0, u);
  }
  if (data.size() % 2 != 0) fail("data: odd number of hex digits");
  if (data.size() > 16) fail("data: more than 8 bytes");
  for (std::size_t i = 0; i < data.size(); i += 2) {
    const int hi = HexDigit(data[i]), lo = HexDigit(data[i + 1]);
    if (hi < 0 || lo < 0) fail("data: not hex");
    r.frame.data[i / 2] = static_cast<std::uint8_t>(hi << 4 | lo);
  }
  r.frame.len = static_cast<std::uint8_t>(data.size() / 2);
}

}  // namespace

CandumpRecord ParseCandumpLine(std::string_view line, const std::string& path, long line_no) {
  const auto fail = [&](const std::string& what) { throw DatasetError(path, line_no, what); };
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  CandumpRecord r;
  std::size_t pos = 0;
  if (!ParseTimestamp(Word(line, pos), r.frame.rx_ns))
    fail("timestamp: '(SECONDS.FRACTION)' expected");
  const std::string_view iface = Word(line, pos);
  if (iface.empty()) fail("interface: missing");
  r.interface = std::string(iface);
  const std::string_view frame = Word(line, pos);
  if (frame.empty()) fail("frame: missing");
  ParseFrame(frame, r, fail);
  const std::string_view dir = Word(line, pos);
  if (!dir.empty() && dir != "R" && dir != "T") fail("unexpected field after the frame");
  if (!Word(line, pos).empty()) fail("unexpected field after the frame");
  return r;
}

std::vector<CandumpRecord> ReadCandumpLog(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw DatasetError(path, 0, "cannot open");
  std::vector<CandumpRecord> out;
  long n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    out.push_back(ParseCandumpLine(std::string_view(line).substr(first), path, n));
  }
  return out;
}

bool LooksLikeCandump(std::string_view text) {
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    std::string_view line =
        text.substr(pos, nl == std::string_view::npos ? text.size() - pos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    return line.size() > first + 1 && line[first] == '(' && line[first + 1] >= '0' &&
           line[first + 1] <= '9';
  }
  return false;
}

}  // namespace hil::estimator::datasets

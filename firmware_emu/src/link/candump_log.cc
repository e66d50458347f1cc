#include "hil/firmware_emu/link/candump_log.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "hil/firmware_emu/link/hex_text.h"

namespace hil::link {
namespace {

constexpr char kHexUpper[] = "0123456789ABCDEF";

// Reads `digits` hex digits at the front of `s`; nothing if any is not hex.
std::optional<std::uint32_t> TakeHex(std::string_view& s, std::size_t digits) {
  if (s.size() < digits) return std::nullopt;
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < digits; ++i) {
    const int h = HexValue(s[i]);
    if (h < 0) return std::nullopt;
    v = (v << 4) | static_cast<std::uint32_t>(h);
  }
  s.remove_prefix(digits);
  return v;
}

// Data bytes as hex pairs, optionally separated by '.', at most `max_len`; a trailing `_<dlc>`
// (len8_dlc) is accepted and ignored. False on anything else.
bool ParseData(std::string_view s, std::size_t max_len, CanWireFrame& f) {
  std::size_t n = 0;
  while (!s.empty()) {
    if (s.front() == '.') {
      s.remove_prefix(1);
      continue;
    }
    if (s.front() == '_') {
      f.len = static_cast<std::uint8_t>(n);
      return s.size() == 2 && HexValue(s[1]) >= 9 && n == 8 && !f.fd;
    }
    const auto byte = TakeHex(s, 2);
    if (!byte || n == max_len) return false;
    f.data[n++] = static_cast<std::uint8_t>(*byte);
  }
  f.len = static_cast<std::uint8_t>(n);
  return true;
}

}  // namespace

std::string FormatCanFrameText(const CanWireFrame& f) {
  std::string out;
  out.reserve(16 + 2 * f.len);
  if (f.error) {
    PutHex(out, (f.id & 0x1FFFFFFFU) | kCanErrFlag, 8);
  } else if (f.extended) {
    PutHex(out, f.id & 0x1FFFFFFFU, 8);
  } else {
    PutHex(out, f.id & 0x7FFU, 3);
  }
  out += '#';
  if (f.rtr && !f.fd && !f.error) {
    out += 'R';
    if (f.len > 0 && f.len <= 8) out += kHexUpper[f.len];
    return out;
  }
  const std::uint8_t len = std::min<std::uint8_t>(f.len, f.fd ? 64 : 8);
  if (f.fd) {
    out += '#';
    out += kHexUpper[f.fd_flags & 0xF];
  }
  for (std::uint8_t i = 0; i < len; ++i) PutHex(out, f.data[i], 2);
  return out;
}

std::optional<CanWireFrame> ParseCanFrameText(std::string_view s) {
  const std::size_t hash = s.find('#');
  if (hash != 3 && hash != 8) return std::nullopt;
  std::string_view id_text = s.substr(0, hash);
  const auto id = TakeHex(id_text, hash);
  if (!id) return std::nullopt;
  CanWireFrame f;
  if (hash == 3) {
    if (*id > 0x7FF) return std::nullopt;
    f.id = *id;
  } else if (*id & kCanErrFlag) {
    f.error = true;
    f.extended = true;
    f.id = *id & 0x1FFFFFFFU;
  } else {
    f.extended = true;
    f.id = *id & 0x1FFFFFFFU;
  }
  s.remove_prefix(hash + 1);
  if (!s.empty() && (s.front() == 'R' || s.front() == 'r')) {
    if (f.error) return std::nullopt;
    f.rtr = true;
    s.remove_prefix(1);
    if (s.empty()) return f;
    const int len = HexValue(s.front());
    if (s.size() != 1 || len < 0 || len > 8) return std::nullopt;
    f.len = static_cast<std::uint8_t>(len);
    return f;
  }
  if (!s.empty() && s.front() == '#') {
    if (f.error) return std::nullopt;
    f.fd = true;
    s.remove_prefix(1);
    const auto flags = TakeHex(s, 1);
    if (!flags) return std::nullopt;
    f.fd_flags = static_cast<std::uint8_t>(*flags);
    if (!ParseData(s, 64, f) || !IsValidFdLength(f.len)) return std::nullopt;
    return f;
  }
  if (!ParseData(s, 8, f)) return std::nullopt;
  return f;
}

std::string FormatCandumpLine(const CandumpRecord& r, int iface_width) {
  std::int64_t sec = ToNs(r.t) / 1000000000LL;
  std::int64_t ns = ToNs(r.t) % 1000000000LL;
  if (ns < 0) {
    ns += 1000000000LL;
    --sec;
  }
  char head[64];
  std::snprintf(head, sizeof head, "(%010lld.%06lld) ", static_cast<long long>(sec),
                static_cast<long long>(ns / 1000));
  std::string out = head;
  if (static_cast<int>(r.iface.size()) < iface_width)
    out.append(static_cast<std::size_t>(iface_width) - r.iface.size(), ' ');
  out += r.iface;
  out += ' ';
  out += FormatCanFrameText(r.frame);
  return out;
}

std::optional<CandumpRecord> ParseCandumpLine(std::string_view line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
  if (line.empty() || line.front() != '(') return std::nullopt;
  const std::size_t close = line.find(')');
  const std::size_t dot = line.find('.');
  if (close == std::string_view::npos || dot == std::string_view::npos || dot > close)
    return std::nullopt;
  CandumpRecord r;
  std::int64_t sec = 0, frac_ns = 0;
  if (dot == 1) return std::nullopt;
  // nanoseconds since 1970 fit 64 bits until 2262: longer second counts are not timestamps
  constexpr std::int64_t kMaxSeconds = 9'000'000'000LL;
  for (std::size_t i = 1; i < dot; ++i) {
    if (line[i] < '0' || line[i] > '9' || i > 19) return std::nullopt;
    sec = sec * 10 + (line[i] - '0');
    if (sec > kMaxSeconds) return std::nullopt;
  }
  std::int64_t scale = 100000000;  // first fraction digit is 10^8 ns
  for (std::size_t i = dot + 1; i < close; ++i) {
    if (line[i] < '0' || line[i] > '9') return std::nullopt;
    frac_ns += (line[i] - '0') * scale;
    scale /= 10;
  }
  if (dot + 1 == close) return std::nullopt;
  r.t = UnixTimeFromNs(sec * 1000000000LL + frac_ns);
  // fields after the timestamp, separated by spaces (the interface may be left-padded)
  std::vector<std::string_view> fields;
  std::string_view rest = line.substr(close + 1);
  while (!rest.empty()) {
    const std::size_t start = rest.find_first_not_of(" \t");
    if (start == std::string_view::npos) break;
    rest.remove_prefix(start);
    const std::size_t end = rest.find_first_of(" \t");
    fields.push_back(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end);
  }
  if (fields.size() < 2 || fields.size() > 3) return std::nullopt;
  if (fields.size() == 3) {
    if (fields[2] != "T" && fields[2] != "R") return std::nullopt;
    r.direction = fields[2][0];
  }
  r.iface = std::string(fields[0]);
  const auto frame = ParseCanFrameText(fields[1]);
  if (!frame) return std::nullopt;
  r.frame = *frame;
  return r;
}

CandumpLogWriter::CandumpLogWriter(const std::string& path) : out_(path) {
  if (!out_) throw std::runtime_error("cannot write the CAN log " + path);
}

void CandumpLogWriter::Write(const CandumpRecord& r) {
  out_ << FormatCandumpLine(r) << '\n';
  out_.flush();
  ++lines_;
}

CandumpLog ReadCandumpLog(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the CAN log " + path);
  CandumpLog log;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() != '(') {
      ++log.skipped_lines;
      continue;
    }
    if (auto r = ParseCandumpLine(line))
      log.records.push_back(std::move(*r));
    else
      ++log.unreadable_lines;
  }
  return log;
}

}  // namespace hil::link

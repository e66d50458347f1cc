#include "hil/harness/dut/nmea_sentence.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace hil::harness {
namespace {

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::optional<double> ToDouble(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return std::nullopt;
  return v;
}

}  // namespace

NmeaParse ParseNmeaSentence(std::string_view line) {
  NmeaParse r;
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
  if (line.empty() || line.front() != '$') {
    r.error = "does not start with '$'";
    return r;
  }
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos) {
    r.error = "no checksum ('*HH' missing)";
    return r;
  }
  if (line.size() != star + 3) {
    r.error = "checksum must be exactly two hex digits at the end";
    return r;
  }
  const int hi = HexDigit(line[star + 1]), lo = HexDigit(line[star + 2]);
  if (hi < 0 || lo < 0) {
    r.error = "checksum is not hexadecimal";
    return r;
  }
  unsigned x = 0;
  for (std::size_t i = 1; i < star; ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    if (c < 0x20 || c > 0x7e || c == '$') {
      r.error = "invalid character in sentence body";
      return r;
    }
    x ^= c;
  }
  if (static_cast<int>(x) != hi * 16 + lo) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "checksum mismatch (computed %02X, sent %c%c)", x,
                  line[star + 1], line[star + 2]);
    r.error = buf;
    return r;
  }
  NmeaSentence s;
  const std::string body(line.substr(1, star - 1));
  std::size_t start = 0;
  bool first = true;
  for (;;) {
    const std::size_t comma = body.find(',', start);
    const std::string f =
        body.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (first)
      s.address = f;
    else
      s.fields.push_back(f);
    first = false;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (s.address.empty()) {
    r.error = "empty address field";
    return r;
  }
  for (char c : s.address) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      r.error = "address field is not alphanumeric";
      return r;
    }
  }
  r.sentence = std::move(s);
  return r;
}

std::optional<double> NmeaDegrees(const std::string& value, const std::string& hemisphere) {
  const auto v = ToDouble(value);
  if (!v || *v < 0) return std::nullopt;
  const double deg = std::floor(*v / 100.0);
  const double min = *v - deg * 100.0;
  if (min >= 60.0) return std::nullopt;
  double d = deg + min / 60.0;
  if (hemisphere == "S" || hemisphere == "W")
    d = -d;
  else if (hemisphere != "N" && hemisphere != "E")
    return std::nullopt;
  return d;
}

std::optional<double> NmeaTimeOfDay(const std::string& value) {
  if (value.size() < 6) return std::nullopt;
  for (std::size_t i = 0; i < 6; ++i) {
    if (!std::isdigit(static_cast<unsigned char>(value[i]))) return std::nullopt;
  }
  const int hh = std::atoi(value.substr(0, 2).c_str()), mm = std::atoi(value.substr(2, 2).c_str());
  const auto ss = ToDouble(value.substr(4));
  if (!ss || hh > 23 || mm > 59 || *ss >= 61.0) return std::nullopt;
  return hh * 3600.0 + mm * 60.0 + *ss;
}

}  // namespace hil::harness

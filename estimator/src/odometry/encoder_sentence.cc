#include "hil/estimator/odometry/encoder_sentence.h"

#include <charconv>
#include <cstdio>

namespace hil::estimator::odometry {
namespace {

unsigned Checksum(std::string_view body) {
  unsigned x = 0;
  for (const char c : body) x ^= static_cast<unsigned char>(c);
  return x;
}

// The next comma-separated field of `s` from `pos` (moved past its comma).
std::string_view NextField(std::string_view s, std::size_t& pos) {
  const std::size_t comma = s.find(',', pos);
  const std::size_t end = comma == std::string_view::npos ? s.size() : comma;
  const std::string_view f = s.substr(pos, end - pos);
  pos = comma == std::string_view::npos ? s.size() : comma + 1;
  return f;
}

bool ParseInt(std::string_view f, std::int64_t& v) {
  if (f.empty()) return false;
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
  return r.ec == std::errc() && r.ptr == f.data() + f.size();
}

// hhmmss.ss (exactly two decimals) as nanoseconds since midnight.
std::optional<std::int64_t> ParseTime(std::string_view f) {
  if (f.size() != 9 || f[6] != '.') return std::nullopt;
  std::int64_t hh = 0, mm = 0, ss = 0, cs = 0;
  if (!ParseInt(f.substr(0, 2), hh) || !ParseInt(f.substr(2, 2), mm) ||
      !ParseInt(f.substr(4, 2), ss) || !ParseInt(f.substr(7, 2), cs) || hh > 23 || mm > 59 ||
      ss > 60 || hh < 0 || mm < 0 || ss < 0 || cs < 0)
    return std::nullopt;
  return ((hh * 60 + mm) * 60 + ss) * 1'000'000'000LL + cs * 10'000'000LL;
}

}  // namespace

EncoderSentenceLine FormatEncoderSentence(const EncoderSentence& s) {
  EncoderSentenceLine out;
  const long long cs = (s.utc_time_of_day_ns + 5'000'000) / 10'000'000;
  const long long sec = cs / 100;
  char body[48];
  const int n = std::snprintf(body, sizeof body, "PHENC,%02lld%02lld%02lld.%02lld,%ld,%ld",
                              sec / 3600 % 24, sec / 60 % 60, sec % 60, cs % 100,
                              static_cast<long>(s.left_counts), static_cast<long>(s.right_counts));
  const int m = std::snprintf(out.bytes.data(), out.bytes.size(), "$%s*%02X\r\n", body,
                              Checksum(std::string_view(body, static_cast<std::size_t>(n))));
  out.size = static_cast<std::size_t>(m);
  return out;
}

std::optional<EncoderSentence> ParseEncoderSentence(std::string_view line) {
  const std::size_t star = line.rfind('*');
  if (line.size() < 8 || line[0] != '$' || star == std::string_view::npos ||
      star + 3 != line.size())
    return std::nullopt;
  const std::string_view body = line.substr(1, star - 1);
  unsigned want = 0;
  const auto r = std::from_chars(line.data() + star + 1, line.data() + line.size(), want, 16);
  if (r.ec != std::errc() || r.ptr != line.data() + line.size() || want != Checksum(body))
    return std::nullopt;
  std::size_t pos = 0;
  if (NextField(body, pos) != "PHENC") return std::nullopt;
  const std::optional<std::int64_t> tod = ParseTime(NextField(body, pos));
  std::int64_t l = 0, rr = 0;
  if (!tod || !ParseInt(NextField(body, pos), l) || !ParseInt(NextField(body, pos), rr) ||
      pos != body.size() || l < INT32_MIN || l > INT32_MAX || rr < INT32_MIN || rr > INT32_MAX)
    return std::nullopt;
  return EncoderSentence{*tod, static_cast<std::int32_t>(l), static_cast<std::int32_t>(rr)};
}

}  // namespace hil::estimator::odometry

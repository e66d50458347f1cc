#include "hil/estimator/drivers/razor_text_decoder.h"

#include <numbers>

namespace hil::estimator::drivers {
namespace {

constexpr std::string_view kRawPrefix = "$,", kRawSuffix = ",#";
constexpr std::string_view kV19Prefix = "!Data:", kV19Suffix = "#";

bool IsStart(char c) { return c == '$' || c == '!'; }
bool IsLineEnd(char c) { return c == '\r' || c == '\n'; }

// a signed decimal integer of at most 5 digits, nothing else
bool ParseInt(std::string_view s, int& out) {
  std::size_t i = 0;
  const bool neg = !s.empty() && s[0] == '-';
  if (neg) i = 1;
  if (s.size() == i || s.size() - i > 5) return false;
  int v = 0;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    v = v * 10 + (s[i] - '0');
  }
  out = neg ? -v : v;
  return true;
}

bool InRange(const std::array<int, 3>& v, int lo, int hi) {
  for (int x : v) {
    if (x < lo || x > hi) return false;
  }
  return true;
}

}  // namespace

Eigen::Vector3d RazorAccel_mps2(const RazorTextSample& s, const RazorScales& k) {
  return Eigen::Vector3d(s.accel_counts[0], s.accel_counts[1], s.accel_counts[2]) *
         k.accel_mps2_per_count;
}

Eigen::Vector3d RazorGyro_radps(const RazorTextSample& s, const RazorScales& k) {
  const Eigen::Vector3d adc(s.gyro_adc[0], s.gyro_adc[1], s.gyro_adc[2]);
  return (adc.array() - k.gyro_zero_adc).matrix() * (k.gyro_dps_per_adc * std::numbers::pi / 180.0);
}

Eigen::Vector3d RazorMag_uT(const RazorTextSample& s, const RazorScales& k) {
  return Eigen::Vector3d(s.mag_counts[0], s.mag_counts[1], s.mag_counts[2]) * k.mag_uT_per_count;
}

bool RazorTextDecoder::ParseLine(std::string_view line, RazorTextSample& out) {
  std::string_view body;
  if (line.starts_with(kRawPrefix) && line.ends_with(kRawSuffix) &&
      line.size() >= kRawPrefix.size() + kRawSuffix.size()) {
    out.format = RazorTextSample::Format::kRaw;
    body = line.substr(kRawPrefix.size(), line.size() - kRawPrefix.size() - kRawSuffix.size());
  } else if (line.starts_with(kV19Prefix) && line.ends_with(kV19Suffix)) {
    out.format = RazorTextSample::Format::kV19;
    body = line.substr(kV19Prefix.size(), line.size() - kV19Prefix.size() - kV19Suffix.size());
  } else {
    return false;
  }
  int v[9];
  std::size_t n = 0, from = 0;
  while (true) {
    const std::size_t comma = body.find(',', from);
    const std::string_view field =
        body.substr(from, comma == std::string_view::npos ? std::string_view::npos : comma - from);
    if (n == 9 || !ParseInt(field, v[n])) return false;
    ++n;
    if (comma == std::string_view::npos) break;
    from = comma + 1;
  }
  if (n != 9) return false;
  for (int i = 0; i < 3; ++i) {
    out.accel_counts[static_cast<std::size_t>(i)] = v[i];
    out.gyro_adc[static_cast<std::size_t>(i)] = v[3 + i];
    out.mag_counts[static_cast<std::size_t>(i)] = v[6 + i];
  }
  return InRange(out.accel_counts, -512, 511) && InRange(out.gyro_adc, 0, 1023) &&
         InRange(out.mag_counts, -4096, 2047);
}

void RazorTextDecoder::Feed(std::string_view bytes) {
  for (char c : bytes) {
    if (!in_line_) {
      if (IsStart(c)) {
        in_line_ = true;
        buf_[0] = c;
        len_ = 1;
      } else if (!IsLineEnd(c)) {
        ++stats_.garbage_bytes;
      }
      continue;
    }
    if (IsStart(c)) {  // a new line cuts the unfinished one
      ++stats_.bad_lines;
      buf_[0] = c;
      len_ = 1;
      continue;
    }
    if (IsLineEnd(c) || len_ == buf_.size()) {
      ++stats_.bad_lines;
      in_line_ = false;
      if (!IsLineEnd(c)) ++stats_.garbage_bytes;
      continue;
    }
    buf_[len_++] = c;
    if (c != '#') continue;
    in_line_ = false;
    RazorTextSample s;
    if (ParseLine(std::string_view(buf_.data(), len_), s)) {
      ++stats_.lines_ok;
      handler_(s);
    } else {
      ++stats_.bad_lines;
    }
  }
}

}  // namespace hil::estimator::drivers

#include "hil/estimator/guidance/base_serial_client.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace hil::estimator::guidance {

BaseCommandLine FormatMotorSpeeds(long left_ticks_per_frame, long right_ticks_per_frame) {
  BaseCommandLine c;
  const int n = std::snprintf(c.bytes.data(), c.bytes.size(), "m %ld %ld\r", left_ticks_per_frame,
                              right_ticks_per_frame);
  c.size = n > 0 ? static_cast<std::size_t>(n) : 0;
  return c;
}

BaseCommandLine FormatReadEncoders() {
  BaseCommandLine c;
  c.bytes[0] = 'e';
  c.bytes[1] = '\r';
  c.size = 2;
  return c;
}

long TicksPerFrame(double wheel_radps, int counts_per_rev, double pid_rate_hz) {
  return std::lround(wheel_radps / (2.0 * std::numbers::pi) * counts_per_rev / pid_rate_hz);
}

bool BaseReplyReader::Feed(char byte) {
  if (byte == '\r') return false;
  if (byte == '\n') {
    const bool dropped = overflow_;
    overflow_ = false;
    if (dropped) {
      ++overlong_;
      size_ = 0;
      return false;
    }
    line_ = buf_;
    line_size_ = size_;
    size_ = 0;
    return true;
  }
  if (overflow_) return false;
  if (size_ == buf_.size()) {
    overflow_ = true;
    return false;
  }
  buf_[size_++] = byte;
  return false;
}

bool ParseEncoderReply(std::string_view line, std::int32_t& left, std::int32_t& right) {
  const auto space = line.find(' ');
  if (space == std::string_view::npos) return false;
  const char* end = line.data() + line.size();
  const auto a = std::from_chars(line.data(), line.data() + space, left);
  if (a.ec != std::errc() || a.ptr != line.data() + space) return false;
  const auto b = std::from_chars(line.data() + space + 1, end, right);
  return b.ec == std::errc() && b.ptr == end;
}

}  // namespace hil::estimator::guidance

#include "hil/firmware_emu/actuator/base_serial_framing.h"

namespace hil::actuator {

bool BaseLineFramer::Feed(char byte) {
  if (byte == '\n') return false;
  if (byte == '\r') {
    const bool was_overflow = overflow_;
    overflow_ = false;
    if (was_overflow) {
      buffer_.clear();
      ++overlong_;
      return false;
    }
    line_.swap(buffer_);
    buffer_.clear();
    return true;
  }
  if (overflow_) return false;
  if (buffer_.size() >= kMaxBaseLineLength) {
    overflow_ = true;
    return false;
  }
  buffer_.push_back(byte);
  return false;
}

}  // namespace hil::actuator

#include "hil/firmware_emu/link/cr_line_framer.h"

namespace hil::link {

bool CrLineFramer::Feed(char byte) {
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
  if (buffer_.size() >= max_length_) {
    overflow_ = true;
    return false;
  }
  buffer_.push_back(byte);
  return false;
}

}  // namespace hil::link

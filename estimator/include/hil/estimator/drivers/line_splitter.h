#pragma once
/// @file
/// Splits a byte stream into text lines in a fixed buffer (no allocation): CR and LF end a line,
/// empty lines are skipped, a line longer than the buffer is dropped whole.

#include <array>
#include <cstddef>
#include <string_view>

namespace hil::estimator::drivers {

template <std::size_t N>
class LineSplitter {
 public:
  /// Calls on_line(std::string_view) for each complete line in `bytes` (without its CR/LF).
  template <typename F>
  void Feed(std::string_view bytes, F&& on_line) {
    for (const char c : bytes) {
      if (c == '\r' || c == '\n') {
        if (size_ > 0 && !overflow_) on_line(std::string_view(buf_.data(), size_));
        size_ = 0;
        overflow_ = false;
      } else if (size_ < buf_.size()) {
        buf_[size_++] = c;
      } else {
        overflow_ = true;
      }
    }
  }

 private:
  std::array<char, N> buf_{};
  std::size_t size_ = 0;
  bool overflow_ = false;
};

}  // namespace hil::estimator::drivers

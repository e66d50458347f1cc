#pragma once
/// @file
/// Framing layer of the differential-drive base's serial protocol (ROSArduinoBridge, see
/// vectors/base_serial/README.md): commands are ASCII lines terminated by CR (13). LF is ignored
/// (a host that ends lines with CR LF works as on the real firmware). A line longer than
/// `kMaxBaseLineLength` is discarded up to its CR and counted.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace hil::actuator {

inline constexpr std::size_t kMaxBaseLineLength = 32;

class BaseLineFramer {
 public:
  /// Feeds one byte; returns true when it completed a line (then `line()` holds it, without CR).
  bool Feed(char byte);
  const std::string& line() const { return line_; }
  std::uint64_t overlong_lines() const { return overlong_; }

 private:
  std::string buffer_;
  std::string line_;
  bool overflow_ = false;
  std::uint64_t overlong_ = 0;
};

}  // namespace hil::actuator

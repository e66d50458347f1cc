#pragma once
/// @file
/// Framing of ASCII command protocols whose lines end with CR (13): the SLCAN adapter's records
/// (vectors/slcan/README.md) and the differential-drive base's ROSArduinoBridge commands
/// (vectors/base_serial/README.md). LF is ignored, so a host that ends lines with CR LF works as on
/// the real devices. A line longer than the framer's limit is discarded up to its CR.

#include <cstddef>
#include <cstdint>
#include <string>

namespace hil::link {

class CrLineFramer {
 public:
  /// `max_length`: the longest line kept (without its CR); a longer one is discarded.
  explicit CrLineFramer(std::size_t max_length) : max_length_(max_length) {}

  /// Feeds one byte; true when it completed a line (then `line()` holds it, without CR).
  bool Feed(char byte);
  const std::string& line() const { return line_; }
  /// Overlong lines whose CR has come (each discarded whole).
  std::uint64_t overlong_lines() const { return overlong_; }
  /// True inside an overlong line, until its CR: the bytes are being discarded.
  bool discarding() const { return overflow_; }

 private:
  std::size_t max_length_;
  std::string buffer_;
  std::string line_;
  bool overflow_ = false;
  std::uint64_t overlong_ = 0;
};

}  // namespace hil::link

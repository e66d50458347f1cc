#pragma once
/// @file
/// The controller's side of the differential-drive base protocol (ROSArduinoBridge,
/// vectors/base_serial/README.md): formats `m L R` and `e` commands and reads the base's reply
/// lines. Independent of the base emulator in firmware_emu; the golden session
/// vectors/base_serial/session_golden.tsv ties the two. Fixed buffers, no allocation.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace hil::estimator::guidance {

/// A command line ready to write (CR-terminated).
struct BaseCommandLine {
  std::array<char, 32> bytes{};
  std::size_t size = 0;
  std::string_view view() const { return {bytes.data(), size}; }
};

/// `m <left> <right>\r`: targets in encoder ticks per PID frame.
BaseCommandLine FormatMotorSpeeds(long left_ticks_per_frame, long right_ticks_per_frame);
/// `e\r`.
BaseCommandLine FormatReadEncoders();
/// Ticks per PID frame for a wheel speed (rad/s), rounded to the nearest tick.
long TicksPerFrame(double wheel_radps, int counts_per_rev, double pid_rate_hz);

/// Splits the base's replies into lines (CR LF or LF terminated; CR dropped). Lines longer than
/// the buffer are discarded and counted.
class BaseReplyReader {
 public:
  /// Feeds one byte; true when a line is complete (then `line()` holds it).
  bool Feed(char byte);
  std::string_view line() const { return {line_.data(), line_size_}; }
  std::uint64_t overlong() const { return overlong_; }

 private:
  std::array<char, 64> buf_{};
  std::size_t size_ = 0;
  std::array<char, 64> line_{};
  std::size_t line_size_ = 0;
  bool overflow_ = false;
  std::uint64_t overlong_ = 0;
};

/// Parses an encoder reply "<left> <right>"; false when the line is not one (e.g. "OK").
bool ParseEncoderReply(std::string_view line, std::int32_t& left, std::int32_t& right);

}  // namespace hil::estimator::guidance

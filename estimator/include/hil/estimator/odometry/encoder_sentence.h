#pragma once
/// @file
/// The wheel-odometry input of navd (`[odometry] device`): the base's encoder counts as one
/// NMEA-0183-style proprietary sentence per reading,
///   `$PHENC,hhmmss.ss,<left>,<right>*hh` CR LF
/// hhmmss.ss: the UTC time of the reading (the controller stamps it with the time of the
/// navigation solution it answered when it asked the base for `e`); left, right: the base's
/// cumulative signed encoder counts (ROSArduinoBridge `e` reply, 32-bit wrapping); hh: the NMEA
/// checksum (XOR of the bytes between `$` and `*`). Fixed buffers, no allocation.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace hil::estimator::odometry {

struct EncoderSentence {
  std::int64_t utc_time_of_day_ns = 0;  ///< 0 … 86400 s, centisecond resolution
  std::int32_t left_counts = 0, right_counts = 0;
};

struct EncoderSentenceLine {
  std::array<char, 64> bytes{};
  std::size_t size = 0;
  std::string_view view() const { return {bytes.data(), size}; }
};

/// The sentence with CR LF (the time rounded to centiseconds).
EncoderSentenceLine FormatEncoderSentence(const EncoderSentence& s);
/// One line without CR LF; nullopt when it is not a well-formed `$PHENC` with a good checksum.
std::optional<EncoderSentence> ParseEncoderSentence(std::string_view line);

}  // namespace hil::estimator::odometry

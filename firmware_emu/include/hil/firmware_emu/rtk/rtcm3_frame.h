#pragma once
/// @file
/// The RTCM 3 transport layer (RTCM 10403.3 §4): preamble 0xD3, 6 reserved bits (0), a 10-bit
/// message length (0–1023 bytes), the message body, then CRC-24Q over preamble, header and
/// body (generator 0x1864CFB, initial value 0, transmitted most significant byte first).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hil::rtcm3 {

inline constexpr unsigned char kPreamble = 0xD3;
inline constexpr std::size_t kMaxBodyBytes = 1023;

/// CRC-24Q (Qualcomm) of `bytes`.
std::uint32_t Crc24q(std::string_view bytes);
/// The whole frame of one message body.
/// @throws std::length_error when the body is longer than 1023 bytes.
std::string Frame(std::string_view body);

/// What a stream split into frames holds.
struct SplitResult {
  std::vector<std::string> bodies;  ///< message bodies of the frames whose CRC matched
  std::size_t crc_errors = 0;       ///< frames (preamble and length found) whose CRC did not
  std::size_t skipped_bytes = 0;    ///< bytes outside any frame
};
/// Splits a byte stream into frames (resynchronises on the next preamble after a bad CRC).
SplitResult Split(std::string_view stream);
/// Message number (DF002, the body's first 12 bits); 0 for an empty body.
int MessageNumber(std::string_view body);

}  // namespace hil::rtcm3

#pragma once
/// @file
/// Bit-level packing of RTCM 3 message bodies: fields are written most significant bit first,
/// one after the other without padding (RTCM 10403.3 §3.4); signed fields are two's complement.
/// A reader of the same layout serves the tests and the stream splitter.

#include <cstdint>
#include <string>
#include <string_view>

namespace hil::rtcm3 {

/// Appends fields to a message body.
class BitWriter {
 public:
  /// Appends the low `bits` bits of `value` (1–64).
  void PutUnsigned(std::uint64_t value, int bits);
  /// Appends `value` as a `bits`-bit two's complement field (1–64).
  void PutSigned(std::int64_t value, int bits);
  /// Bits written so far.
  std::size_t bit_count() const { return bit_count_; }
  /// The body, zero-padded to whole bytes (RTCM 3 messages end on a byte boundary).
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  std::size_t bit_count_ = 0;
};

/// Reads fields of a message body.
class BitReader {
 public:
  explicit BitReader(std::string_view bytes) : bytes_(bytes) {}
  /// The next `bits` bits (1–64) as unsigned; 0 past the end (check ok()).
  std::uint64_t GetUnsigned(int bits);
  /// The next `bits` bits as two's complement.
  std::int64_t GetSigned(int bits);
  std::size_t position() const { return pos_; }
  bool ok() const { return pos_ <= bytes_.size() * 8; }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

}  // namespace hil::rtcm3

#include "hil/firmware_emu/rtk/rtcm3_bits.h"

#include <algorithm>

namespace hil::rtcm3 {

void BitWriter::PutUnsigned(std::uint64_t value, int bits) {
  // the free bits of the last byte at a time, most significant first
  while (bits > 0) {
    const auto used = static_cast<int>(bit_count_ % 8);
    if (used == 0) bytes_.push_back('\0');
    const int take = std::min(8 - used, bits);
    const auto chunk = static_cast<unsigned>((value >> (bits - take)) & ((1U << take) - 1U));
    const auto shift = static_cast<unsigned>(8 - used - take);
    bytes_.back() = static_cast<char>(static_cast<unsigned char>(bytes_.back()) | (chunk << shift));
    bits -= take;
    bit_count_ += static_cast<std::size_t>(take);
  }
}

void BitWriter::PutSigned(std::int64_t value, int bits) {
  PutUnsigned(static_cast<std::uint64_t>(value), bits);
}

std::uint64_t BitReader::GetUnsigned(int bits) {
  std::uint64_t v = 0;
  for (int i = 0; i < bits; ++i, ++pos_) {
    std::uint64_t bit = 0;
    if (pos_ < bytes_.size() * 8) {
      const auto byte = static_cast<unsigned char>(bytes_[pos_ / 8]);
      bit = (byte >> (7 - pos_ % 8)) & 1U;
    }
    v = (v << 1) | bit;
  }
  return v;
}

std::int64_t BitReader::GetSigned(int bits) {
  const std::uint64_t u = GetUnsigned(bits);
  if (bits < 64 && (u >> (bits - 1)) & 1U) {
    return static_cast<std::int64_t>(u | (~std::uint64_t{0} << bits));
  }
  return static_cast<std::int64_t>(u);
}

}  // namespace hil::rtcm3

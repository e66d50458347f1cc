#include "hil/firmware_emu/rtk/rtcm3_bits.h"

namespace hil::rtcm3 {

void BitWriter::PutUnsigned(std::uint64_t value, int bits) {
  for (int i = bits - 1; i >= 0; --i) {
    if (bit_count_ % 8 == 0) bytes_.push_back('\0');
    if ((value >> i) & 1U) {
      const auto shift = static_cast<unsigned>(7 - bit_count_ % 8);
      bytes_.back() = static_cast<char>(static_cast<unsigned char>(bytes_.back()) | (1U << shift));
    }
    ++bit_count_;
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

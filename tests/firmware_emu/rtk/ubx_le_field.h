#pragma once
// A little-endian field of a UBX payload read by its offset, as the interface description lays
// it out: the tests' own reader, independent of the encoders.
#include <cstdint>
#include <string_view>

namespace hil::rtk::test {

/// `n` bytes (1–8) at `off` of `payload`, sign-extended when `is_signed`.
inline std::int64_t Le(std::string_view payload, std::size_t off, std::size_t n, bool is_signed) {
  std::uint64_t v = 0;
  for (std::size_t k = 0; k < n; ++k)
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(payload[off + k])) << (8 * k);
  if (is_signed && n < 8 && (v >> (8 * n - 1) & 1U) != 0) v |= ~0ULL << (8 * n);
  return static_cast<std::int64_t>(v);
}

}  // namespace hil::rtk::test

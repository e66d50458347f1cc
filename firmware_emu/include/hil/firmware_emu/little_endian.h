#pragma once
/// @file
/// Little-endian integer fields, for both sides of the wire: the emulators write them into frames
/// (UBX, MCU, J1939/ISOBUS, WitMotion, Benewake, RPLIDAR, LinkTrack) and read the host's commands;
/// the harness reads them back from captures and logs (validate, datasets, dut). One place, so
/// every frame agrees on byte order and on how a signed value is carried (two's complement).
///
/// Byte containers: `std::string`, `std::vector<std::uint8_t>`, `std::array<std::uint8_t, N>`, or
/// anything indexable whose elements are one byte.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace hil {

/// The unsigned value of the n (1 to 8) little-endian bytes at p.
constexpr std::uint64_t LeRead(const unsigned char* p, int n) {
  std::uint64_t v = 0;
  for (int k = n - 1; k >= 0; --k) v = (v << 8) | p[k];
  return v;
}

/// The unsigned value of the n (1 to 8) little-endian bytes of b from offset at.
/// @pre at + n <= b.size()
inline std::uint64_t LeRead(std::string_view b, std::size_t at, int n) {
  return LeRead(reinterpret_cast<const unsigned char*>(b.data()) + at, n);
}

/// The integer T (sizeof(T) bytes, two's complement when signed) at p.
template <std::integral T>
constexpr T LeRead(const unsigned char* p) {
  return static_cast<T>(static_cast<std::make_unsigned_t<T>>(LeRead(p, sizeof(T))));
}

/// The integer T (sizeof(T) bytes, two's complement when signed) of b at offset at.
/// @pre at + sizeof(T) <= b.size()
template <std::integral T>
T LeRead(std::string_view b, std::size_t at) {
  return LeRead<T>(reinterpret_cast<const unsigned char*>(b.data()) + at);
}

/// Writes the low n (1 to 8) bytes of v, least significant first, over b[at] … b[at + n - 1].
template <typename Bytes>
constexpr void LePut(Bytes& b, std::size_t at, std::uint64_t v, int n) {
  using Byte = std::remove_cvref_t<decltype(b[0])>;
  for (int k = 0; k < n; ++k)
    b[at + static_cast<std::size_t>(k)] = static_cast<Byte>((v >> (8 * k)) & 0xFFu);
}

/// Appends the low n (1 to 8) bytes of v, least significant first, to b.
template <typename Bytes>
constexpr void LeAppend(Bytes& b, std::uint64_t v, int n) {
  using Byte = typename Bytes::value_type;
  for (int k = 0; k < n; ++k) b.push_back(static_cast<Byte>((v >> (8 * k)) & 0xFFu));
}

}  // namespace hil

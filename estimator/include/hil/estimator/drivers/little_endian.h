#pragma once
/// @file
/// Little-endian field reads for the device decoders (WitMotion, Benewake, RPLIDAR, UWB frames).

#include <cstdint>

namespace hil::estimator::drivers {

/// The unsigned 16-bit little-endian value at p.
inline std::uint16_t LeU16(const unsigned char* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

/// The signed (two's complement) 16-bit little-endian value at p.
inline std::int16_t LeI16(const unsigned char* p) { return static_cast<std::int16_t>(LeU16(p)); }

/// The unsigned 32-bit little-endian value at p.
inline std::uint32_t LeU32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

}  // namespace hil::estimator::drivers

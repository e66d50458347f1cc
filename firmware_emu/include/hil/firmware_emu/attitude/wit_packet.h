#pragma once
/// @file
/// The WitMotion standard protocol's 11-byte output packet (seeds_001_003.md §C.1):
/// `55 TYPE D0L D0H D1L D1H D2L D2H D3L D3H SUM`, four little-endian int16 fields, SUM = low 8 bits
/// of the sum of bytes 0–9. Also the scalings of the packets this emulator sends and the 5-byte
/// host command `FF AA REG DATAL DATAH`.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace hil::wit {

inline constexpr std::uint8_t kHeader = 0x55;
inline constexpr std::size_t kPacketSize = 11;

enum class PacketType : std::uint8_t {
  kAcceleration = 0x51,
  kAngularRate = 0x52,
  kAngle = 0x53,
  kMagnetic = 0x54,
  kRegisterRead = 0x5F,
};

/// Full-scale values of the int16 fields (value = raw / 32768 × full scale).
inline constexpr double kAccelFullScale_g = 16.0;
inline constexpr double kRateFullScale_dps = 2000.0;
inline constexpr double kAngleFullScale_deg = 180.0;
inline constexpr double kTemperatureLsb_c = 0.01;

/// Sum-8 over `bytes` (the checksum when given bytes 0–9).
std::uint8_t Sum8(std::string_view bytes);

/// The 11-byte packet of `type` with fields d.
std::string EncodePacket(std::uint8_t type, const std::array<std::int16_t, 4>& d);

/// value / full_scale × 32768, rounded, saturated to the int16 range.
std::int16_t ScaleToRaw(double value, double full_scale);

/// An angle in degrees as the sensor encodes it: wrapped into [−180°, 180°) then scaled; +180°
/// (raw 32768) is not representable and reads −180°.
std::int16_t AngleToRaw(double angle_deg);

/// The host's configuration command for register `reg` ← value.
std::string EncodeWriteCommand(std::uint8_t reg, std::uint16_t value);

}  // namespace hil::wit

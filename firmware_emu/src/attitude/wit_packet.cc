#include "hil/firmware_emu/attitude/wit_packet.h"

#include <cmath>

#include "hil/firmware_emu/little_endian.h"

namespace hil::wit {

std::uint8_t Sum8(std::string_view bytes) {
  unsigned sum = 0;
  for (char c : bytes) sum += static_cast<unsigned char>(c);
  return static_cast<std::uint8_t>(sum & 0xFFu);
}

std::string EncodePacket(std::uint8_t type, const std::array<std::int16_t, 4>& d) {
  std::string p(kPacketSize, '\0');
  p[0] = static_cast<char>(kHeader);
  p[1] = static_cast<char>(type);
  for (std::size_t i = 0; i < 4; ++i) LePut(p, 2 + 2 * i, static_cast<std::uint16_t>(d[i]), 2);
  p[10] = static_cast<char>(Sum8(std::string_view(p).substr(0, 10)));
  return p;
}

std::int16_t ScaleToRaw(double value, double full_scale) {
  if (!std::isfinite(value)) return 0;
  const double raw = std::round(value / full_scale * 32768.0);
  if (raw >= 32767.0) return 32767;
  if (raw <= -32768.0) return -32768;
  return static_cast<std::int16_t>(raw);
}

std::int16_t AngleToRaw(double angle_deg) {
  if (!std::isfinite(angle_deg)) return 0;
  double a = std::fmod(angle_deg + 180.0, 360.0);
  if (a < 0) a += 360.0;
  // a in [0, 360): raw in [0, 65536) then shifted to [−32768, 32768); 65536 wraps to 0 (= −180°).
  long raw = std::lround(a / 360.0 * 65536.0);
  if (raw >= 65536) raw -= 65536;
  return static_cast<std::int16_t>(raw - 32768);
}

std::string EncodeWriteCommand(std::uint8_t reg, std::uint16_t value) {
  std::string c{static_cast<char>(0xFF), static_cast<char>(0xAA), static_cast<char>(reg)};
  LeAppend(c, value, 2);
  return c;
}

}  // namespace hil::wit

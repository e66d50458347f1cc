#include "hil/firmware_emu/rangefinder/benewake_codec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hil::rangefinder {
namespace {
std::uint8_t Lo(std::uint16_t v) { return static_cast<std::uint8_t>(v & 0xFFu); }
std::uint8_t Hi(std::uint16_t v) { return static_cast<std::uint8_t>(v >> 8); }
std::uint16_t U16At(std::string_view s, std::size_t i) {
  return static_cast<std::uint16_t>(static_cast<unsigned char>(s[i]) |
                                    (static_cast<unsigned char>(s[i + 1]) << 8));
}
}  // namespace

std::array<std::uint8_t, 6> EncodeDataFields(const DataFields& f) {
  return {Lo(f.dist), Hi(f.dist), Lo(f.amp), Hi(f.amp), Lo(f.temp_raw), Hi(f.temp_raw)};
}

DataFields DecodeDataFields(std::string_view frame) {
  return {U16At(frame, 2), U16At(frame, 4), U16At(frame, 6)};
}

std::uint16_t TemperatureToRaw(double temperature_c) {
  const double raw = std::round((temperature_c + 256.0) * 8.0);
  return static_cast<std::uint16_t>(std::clamp(raw, 0.0, 65535.0));
}

double TemperatureFromRaw(std::uint16_t raw) { return raw / 8.0 - 256.0; }

std::string PixLine(double distance_m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f\r\n", std::max(0.0, distance_m));
  return buf;
}

std::string U16Payload(std::uint16_t v) {
  return {static_cast<char>(Lo(v)), static_cast<char>(Hi(v))};
}

std::string U32Payload(std::uint32_t v) {
  std::string s;
  for (int k = 0; k < 4; ++k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xFFu));
  return s;
}

std::optional<std::uint16_t> PayloadU16(std::string_view payload) {
  if (payload.size() != 2) return std::nullopt;
  return U16At(payload, 0);
}

std::optional<std::uint32_t> PayloadU32(std::string_view payload) {
  if (payload.size() != 4) return std::nullopt;
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(payload[k]);
  return v;
}

bool IsSupportedBaud(std::uint32_t baud) {
  static constexpr std::uint32_t kBauds[] = {9600,   14400,  19200,  38400,  56000,
                                             57600,  115200, 128000, 230400, 256000,
                                             460800, 500000, 512000, 921600};
  return std::find(std::begin(kBauds), std::end(kBauds), baud) != std::end(kBauds);
}

}  // namespace hil::rangefinder

#include "hil/firmware_emu/rangefinder/benewake_codec.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hil/firmware_emu/little_endian.h"

namespace hil::rangefinder {

std::array<std::uint8_t, 6> EncodeDataFields(const DataFields& f) {
  std::array<std::uint8_t, 6> b{};
  LePut(b, 0, f.dist, 2);
  LePut(b, 2, f.amp, 2);
  LePut(b, 4, f.temp_raw, 2);
  return b;
}

DataFields DecodeDataFields(std::string_view frame) {
  return {LeRead<std::uint16_t>(frame, 2), LeRead<std::uint16_t>(frame, 4),
          LeRead<std::uint16_t>(frame, 6)};
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
  std::string s;
  LeAppend(s, v, 2);
  return s;
}

std::string U32Payload(std::uint32_t v) {
  std::string s;
  LeAppend(s, v, 4);
  return s;
}

std::optional<std::uint16_t> PayloadU16(std::string_view payload) {
  if (payload.size() != 2) return std::nullopt;
  return LeRead<std::uint16_t>(payload, 0);
}

std::optional<std::uint32_t> PayloadU32(std::string_view payload) {
  if (payload.size() != 4) return std::nullopt;
  return LeRead<std::uint32_t>(payload, 0);
}

bool IsSupportedBaud(std::uint32_t baud) {
  static constexpr std::uint32_t kBauds[] = {9600,   14400,  19200,  38400,  56000,
                                             57600,  115200, 128000, 230400, 256000,
                                             460800, 500000, 512000, 921600};
  return std::find(std::begin(kBauds), std::end(kBauds), baud) != std::end(kBauds);
}

}  // namespace hil::rangefinder

#pragma once
// A minimal reader of MCU protocol v1 frames for the tests (the estimator has its own decoder):
// splits a byte stream into frames, checks the CRC, reads the little-endian fields.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "hil/firmware_emu/mcu/mcu_frame.h"

namespace hil::mcu::test {

struct ReadFrame {
  std::uint8_t type = 0;
  std::uint16_t sequence = 0;
  std::uint32_t tick = 0;
  std::vector<std::uint8_t> payload;
  bool crc_ok = false;
  std::int16_t I16(std::size_t at) const {
    return static_cast<std::int16_t>(payload[at] | (payload[at + 1] << 8));
  }
  std::uint16_t U16(std::size_t at) const {
    return static_cast<std::uint16_t>(payload[at] | (payload[at + 1] << 8));
  }
  std::uint32_t U32(std::size_t at) const {
    return static_cast<std::uint32_t>(payload[at]) |
           (static_cast<std::uint32_t>(payload[at + 1]) << 8) |
           (static_cast<std::uint32_t>(payload[at + 2]) << 16) |
           (static_cast<std::uint32_t>(payload[at + 3]) << 24);
  }
  float F32(std::size_t at) const {
    const std::uint32_t u = U32(at);
    float f;
    std::memcpy(&f, &u, 4);
    return f;
  }
};

/// One frame from one whole message (as a device emits them).
inline ReadFrame ParseFrame(const std::string& bytes) {
  ReadFrame f;
  const auto* b = reinterpret_cast<const std::uint8_t*>(bytes.data());
  if (bytes.size() < kHeaderBytes + kCrcBytes || b[0] != kSync1 || b[1] != kSync2) return f;
  f.type = b[3];
  const std::size_t n = b[4];
  if (bytes.size() != kHeaderBytes + n + kCrcBytes) return f;
  f.sequence = static_cast<std::uint16_t>(b[5] | (b[6] << 8));
  f.tick = static_cast<std::uint32_t>(b[7]) | (static_cast<std::uint32_t>(b[8]) << 8) |
           (static_cast<std::uint32_t>(b[9]) << 16) | (static_cast<std::uint32_t>(b[10]) << 24);
  f.payload.assign(b + kHeaderBytes, b + kHeaderBytes + n);
  const std::vector<std::uint8_t> body(b + 2, b + kHeaderBytes + n);
  const auto crc = static_cast<std::uint16_t>(b[kHeaderBytes + n] | (b[kHeaderBytes + n + 1] << 8));
  f.crc_ok = Crc16CcittFalse(body) == crc;
  return f;
}

}  // namespace hil::mcu::test

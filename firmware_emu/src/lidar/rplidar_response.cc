#include "hil/firmware_emu/lidar/rplidar_response.h"

#include <algorithm>

#include "hil/firmware_emu/lidar/rplidar_request.h"
#include "hil/firmware_emu/little_endian.h"

namespace hil::lidar {
std::string EncodeU32(std::uint32_t v) {
  std::string s;
  LeAppend(s, v, 4);
  return s;
}

std::string EncodeDescriptor(std::uint32_t length, bool multiple, DataType type) {
  std::string d{static_cast<char>(kSyncA5), static_cast<char>(kSync5A)};
  d += EncodeU32((length & 0x3FFFFFFFu) | (multiple ? 0x40000000u : 0u));
  d.push_back(static_cast<char>(type));
  return d;
}

std::string EncodeDeviceInfo(const DeviceInfo& d) {
  std::string s{static_cast<char>(d.model), static_cast<char>(d.firmware_minor),
                static_cast<char>(d.firmware_major), static_cast<char>(d.hardware)};
  for (const std::uint8_t b : d.serial) s.push_back(static_cast<char>(b));
  return s;
}

std::string EncodeHealth(std::uint8_t status, std::uint16_t error_code) {
  std::string s(1, static_cast<char>(status));
  LeAppend(s, error_code, 2);
  return s;
}

std::string EncodeSampleRate(std::uint16_t standard_us, std::uint16_t express_us) {
  std::string s;
  LeAppend(s, standard_us, 2);
  LeAppend(s, express_us, 2);
  return s;
}

std::string EncodeNode(const ScanNode& n) {
  std::string s;
  const unsigned s_bit = n.start ? 1u : 0u;
  s.push_back(static_cast<char>(((n.quality & 0x3Fu) << 2) | ((s_bit ^ 1u) << 1) | s_bit));
  LeAppend(s, static_cast<std::uint16_t>((n.angle_q6 << 1) | 1u), 2);
  LeAppend(s, n.distance_q2, 2);
  return s;
}

std::string EncodeCapsule(const ExpressCapsule& c) {
  std::string s(2, '\0');
  LeAppend(
      s, static_cast<std::uint16_t>((c.start_angle_q6 & 0x7FFFu) | (c.new_scan ? 0x8000u : 0u)), 2);
  for (std::size_t k = 0; k < kCabins; ++k) {
    // distance in the top 14 bits of each u16 (mm), angle-offset bits 0; offsets byte 0
    LeAppend(s, static_cast<std::uint16_t>(std::min<unsigned>(c.distance_mm[2 * k], 0x3FFF) << 2),
             2);
    LeAppend(s,
             static_cast<std::uint16_t>(std::min<unsigned>(c.distance_mm[2 * k + 1], 0x3FFF) << 2),
             2);
    s.push_back('\0');
  }
  unsigned cs = 0;
  for (std::size_t k = 2; k < s.size(); ++k) cs ^= static_cast<unsigned char>(s[k]);
  s[0] = static_cast<char>(0xA0u | (cs & 0x0Fu));
  s[1] = static_cast<char>(0x50u | (cs >> 4));
  return s;
}

}  // namespace hil::lidar

#include "hil/firmware_emu/rtk/rtcm3_frame.h"

#include <stdexcept>

namespace hil::rtcm3 {

std::uint32_t Crc24q(std::string_view bytes) {
  constexpr std::uint32_t kPoly = 0x1864CFB;
  std::uint32_t crc = 0;
  for (const char c : bytes) {
    crc ^= static_cast<std::uint32_t>(static_cast<unsigned char>(c)) << 16;
    for (int i = 0; i < 8; ++i) {
      crc <<= 1;
      if (crc & 0x1000000) crc ^= kPoly;
    }
  }
  return crc & 0xFFFFFF;
}

std::string Frame(std::string_view body) {
  if (body.size() > kMaxBodyBytes) {
    throw std::length_error("RTCM 3 message body of " + std::to_string(body.size()) +
                            " bytes (at most 1023)");
  }
  std::string f;
  f.reserve(body.size() + 6);
  f.push_back(static_cast<char>(kPreamble));
  f.push_back(static_cast<char>((body.size() >> 8) & 0x03));  // 6 reserved bits are 0
  f.push_back(static_cast<char>(body.size() & 0xFF));
  f.append(body);
  const std::uint32_t crc = Crc24q(f);
  f.push_back(static_cast<char>((crc >> 16) & 0xFF));
  f.push_back(static_cast<char>((crc >> 8) & 0xFF));
  f.push_back(static_cast<char>(crc & 0xFF));
  return f;
}

SplitResult Split(std::string_view stream) {
  SplitResult r;
  std::size_t i = 0;
  while (i < stream.size()) {
    const auto b0 = static_cast<unsigned char>(stream[i]);
    if (b0 != kPreamble || i + 3 > stream.size()) {
      ++r.skipped_bytes;
      ++i;
      continue;
    }
    const auto b1 = static_cast<unsigned char>(stream[i + 1]);
    const auto b2 = static_cast<unsigned char>(stream[i + 2]);
    const std::size_t len = ((b1 & 0x03U) << 8) | b2;
    if ((b1 & 0xFCU) != 0 || i + 3 + len + 3 > stream.size()) {
      ++r.skipped_bytes;
      ++i;
      continue;
    }
    const std::string_view framed = stream.substr(i, 3 + len);
    const auto c = [&](std::size_t k) {
      return static_cast<std::uint32_t>(static_cast<unsigned char>(stream[i + 3 + len + k]));
    };
    if (Crc24q(framed) != ((c(0) << 16) | (c(1) << 8) | c(2))) {
      ++r.crc_errors;
      ++r.skipped_bytes;
      ++i;
      continue;
    }
    r.bodies.emplace_back(stream.substr(i + 3, len));
    i += 3 + len + 3;
  }
  return r;
}

int MessageNumber(std::string_view body) {
  if (body.size() < 2) return 0;
  return (static_cast<unsigned char>(body[0]) << 4) | (static_cast<unsigned char>(body[1]) >> 4);
}

}  // namespace hil::rtcm3

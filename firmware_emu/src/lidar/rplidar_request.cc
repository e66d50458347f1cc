#include "hil/firmware_emu/lidar/rplidar_request.h"

namespace hil::lidar {

std::string EncodeRequest(std::uint8_t cmd, std::string_view payload) {
  std::string r{static_cast<char>(kSyncA5), static_cast<char>(cmd)};
  if ((cmd & 0x80u) == 0) return r;
  r.push_back(static_cast<char>(payload.size()));
  r.append(payload);
  unsigned cs = 0;
  for (const char c : r) cs ^= static_cast<unsigned char>(c);
  r.push_back(static_cast<char>(cs));
  return r;
}

void RequestReader::Feed(std::string_view bytes) {
  buf_.append(bytes);
  std::size_t i = 0;
  while (i < buf_.size()) {
    if (static_cast<unsigned char>(buf_[i]) != kSyncA5) {
      ++stats_.garbage_bytes, ++i;
      continue;
    }
    if (i + 2 > buf_.size()) break;
    const auto cmd = static_cast<std::uint8_t>(buf_[i + 1]);
    if ((cmd & 0x80u) == 0) {
      ++stats_.requests;
      handler_(RequestFrame{cmd, {}});
      i += 2;
      continue;
    }
    if (i + 3 > buf_.size()) break;
    const std::size_t size = static_cast<unsigned char>(buf_[i + 2]);
    if (i + 4 + size > buf_.size()) break;
    unsigned cs = 0;
    for (std::size_t k = 0; k < 3 + size; ++k) cs ^= static_cast<unsigned char>(buf_[i + k]);
    if (cs != static_cast<unsigned char>(buf_[i + 3 + size])) {
      ++stats_.bad_checksum, ++i;
      continue;
    }
    ++stats_.requests;
    handler_(RequestFrame{cmd, buf_.substr(i + 3, size)});
    i += 4 + size;
  }
  buf_.erase(0, i);
}

}  // namespace hil::lidar

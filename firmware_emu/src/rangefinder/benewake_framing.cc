#include "hil/firmware_emu/rangefinder/benewake_framing.h"

namespace hil::rangefinder {

std::uint8_t Sum8(std::string_view bytes) {
  unsigned sum = 0;
  for (const char c : bytes) sum += static_cast<unsigned char>(c);
  return static_cast<std::uint8_t>(sum & 0xFFu);
}

std::string FrameData(const std::array<std::uint8_t, 6>& payload) {
  std::string f(2, static_cast<char>(kDataHeader));
  for (const std::uint8_t b : payload) f.push_back(static_cast<char>(b));
  f.push_back(static_cast<char>(Sum8(f)));
  return f;
}

std::string FrameCommand(std::uint8_t id, std::string_view payload) {
  std::string f;
  f.push_back(static_cast<char>(kCommandHeader));
  f.push_back(static_cast<char>(payload.size() + 4));
  f.push_back(static_cast<char>(id));
  f.append(payload);
  f.push_back(static_cast<char>(Sum8(f)));
  return f;
}

void CommandReader::Feed(std::string_view bytes) {
  buf_.append(bytes);
  std::size_t i = 0;
  while (i < buf_.size()) {
    if (static_cast<unsigned char>(buf_[i]) != kCommandHeader) {
      ++stats_.garbage_bytes, ++i;
      continue;
    }
    if (i + 2 > buf_.size()) break;
    const std::size_t len = static_cast<unsigned char>(buf_[i + 1]);
    if (len < kMinCommandSize || len > kMaxCommandSize) {
      ++stats_.garbage_bytes, ++i;
      continue;
    }
    if (i + len > buf_.size()) break;
    const std::string_view frame(buf_.data() + i, len);
    const auto cs = static_cast<std::uint8_t>(frame.back());
    const bool zero = cs == 0 && Sum8(frame.substr(0, len - 1)) != 0;
    if (cs != Sum8(frame.substr(0, len - 1)) && !zero) {
      ++stats_.bad_checksum, ++i;
      continue;
    }
    ++stats_.frames;
    if (zero) ++stats_.zero_checksum;
    handler_(CommandFrame{static_cast<std::uint8_t>(frame[2]),
                          std::string(frame.substr(3, len - 4)), zero});
    i += len;
  }
  buf_.erase(0, i);
}

}  // namespace hil::rangefinder

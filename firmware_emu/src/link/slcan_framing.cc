#include "hil/firmware_emu/link/slcan_framing.h"

#include "hil/firmware_emu/link/hex_text.h"

namespace hil::link {
namespace {

// Parses `digits` hex digits at `at`; false on a non-hex digit or a short record.
bool ParseHex(std::string_view s, std::size_t at, int digits, std::uint32_t& out) {
  if (at + static_cast<std::size_t>(digits) > s.size()) return false;
  out = 0;
  for (int i = 0; i < digits; ++i) {
    const int v = HexValue(s[at + static_cast<std::size_t>(i)]);
    if (v < 0) return false;
    out = (out << 4) | static_cast<std::uint32_t>(v);
  }
  return true;
}

}  // namespace

std::string EncodeSlcanFrame(const CanFrame& frame) {
  std::string s;
  s.reserve(kMaxSlcanRecord + 1);
  const char kind = frame.rtr ? 'r' : 't';
  s.push_back(frame.extended ? static_cast<char>(kind - 'a' + 'A') : kind);
  PutHex(s, frame.id, frame.extended ? 8 : 3);
  const int len = frame.len > 8 ? 8 : frame.len;
  s.push_back(static_cast<char>('0' + len));
  if (!frame.rtr) {
    for (int i = 0; i < len; ++i) PutHex(s, frame.data[static_cast<std::size_t>(i)], 2);
  }
  s.push_back('\r');
  return s;
}

SlcanFrameError DecodeSlcanFrame(std::string_view record, CanFrame& out) {
  if (record.empty()) return SlcanFrameError::kNotAFrame;
  const char k = record[0];
  if (k != 't' && k != 'T' && k != 'r' && k != 'R') return SlcanFrameError::kNotAFrame;
  const bool extended = k == 'T' || k == 'R';
  const bool rtr = k == 'r' || k == 'R';
  const int id_digits = extended ? 8 : 3;
  std::uint32_t id = 0;
  if (!ParseHex(record, 1, id_digits, id) || id > (extended ? 0x1FFFFFFFU : 0x7FFU))
    return SlcanFrameError::kBadId;
  const std::size_t at_len = 1 + static_cast<std::size_t>(id_digits);
  if (at_len >= record.size()) return SlcanFrameError::kBadLength;
  const int len = record[at_len] - '0';
  if (len < 0 || len > 8) return SlcanFrameError::kBadLength;
  const std::size_t data_digits = rtr ? 0 : 2 * static_cast<std::size_t>(len);
  if (record.size() != at_len + 1 + data_digits) return SlcanFrameError::kBadData;
  CanFrame f;
  f.t = out.t;
  f.id = id;
  f.extended = extended;
  f.rtr = rtr;
  f.len = static_cast<std::uint8_t>(len);
  for (std::size_t i = 0; i < data_digits / 2; ++i) {
    std::uint32_t b = 0;
    if (!ParseHex(record, at_len + 1 + 2 * i, 2, b)) return SlcanFrameError::kBadData;
    f.data[i] = static_cast<std::uint8_t>(b);
  }
  out = f;
  return SlcanFrameError::kNone;
}

}  // namespace hil::link

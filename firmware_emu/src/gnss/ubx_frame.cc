#include "hil/firmware_emu/gnss/ubx_frame.h"

#include <bit>

#include "hil/firmware_emu/gnss/nmea_sentence.h"
#include "hil/firmware_emu/little_endian.h"

namespace hil::gnss::ubx {
namespace {

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

Writer& Writer::U1(std::uint64_t v) {
  LeAppend(bytes_, v, 1);
  return *this;
}
Writer& Writer::U2(std::uint64_t v) {
  LeAppend(bytes_, v, 2);
  return *this;
}
Writer& Writer::U4(std::uint64_t v) {
  LeAppend(bytes_, v, 4);
  return *this;
}
Writer& Writer::I1(std::int64_t v) {
  LeAppend(bytes_, static_cast<std::uint64_t>(v), 1);
  return *this;
}
Writer& Writer::I2(std::int64_t v) {
  LeAppend(bytes_, static_cast<std::uint64_t>(v), 2);
  return *this;
}
Writer& Writer::I4(std::int64_t v) {
  LeAppend(bytes_, static_cast<std::uint64_t>(v), 4);
  return *this;
}
Writer& Writer::R4(float v) {
  LeAppend(bytes_, std::bit_cast<std::uint32_t>(v), 4);
  return *this;
}
Writer& Writer::R8(double v) {
  LeAppend(bytes_, std::bit_cast<std::uint64_t>(v), 8);
  return *this;
}
Writer& Writer::Chars(std::string_view text, std::size_t width) {
  for (std::size_t i = 0; i < width; ++i)
    bytes_.push_back(i < text.size() ? static_cast<std::uint8_t>(text[i]) : 0);
  return *this;
}
Writer& Writer::Zeros(std::size_t n) {
  bytes_.insert(bytes_.end(), n, 0);
  return *this;
}

std::uint8_t Reader::U1(std::size_t off) const { return off < p_.size() ? p_[off] : 0; }
std::uint16_t Reader::U2(std::size_t off) const {
  return static_cast<std::uint16_t>(U1(off) | (U1(off + 1) << 8));
}
std::uint32_t Reader::U4(std::size_t off) const {
  return static_cast<std::uint32_t>(U2(off)) | (static_cast<std::uint32_t>(U2(off + 2)) << 16);
}
std::int8_t Reader::I1(std::size_t off) const { return static_cast<std::int8_t>(U1(off)); }
std::int16_t Reader::I2(std::size_t off) const { return static_cast<std::int16_t>(U2(off)); }
std::int32_t Reader::I4(std::size_t off) const { return static_cast<std::int32_t>(U4(off)); }

std::pair<std::uint8_t, std::uint8_t> Checksum(std::string_view bytes) {
  std::uint8_t a = 0, b = 0;
  for (char c : bytes) {
    a = static_cast<std::uint8_t>(a + static_cast<std::uint8_t>(c));
    b = static_cast<std::uint8_t>(b + a);
  }
  return {a, b};
}

std::string Frame(std::uint8_t cls, std::uint8_t id, const std::vector<std::uint8_t>& payload) {
  std::string f;
  f.reserve(payload.size() + 8);
  f += static_cast<char>(kSync1);
  f += static_cast<char>(kSync2);
  f += static_cast<char>(cls);
  f += static_cast<char>(id);
  f += static_cast<char>(payload.size() & 0xFFu);
  f += static_cast<char>((payload.size() >> 8) & 0xFFu);
  for (std::uint8_t b : payload) f += static_cast<char>(b);
  const auto [ck_a, ck_b] = Checksum(std::string_view(f).substr(2));
  f += static_cast<char>(ck_a);
  f += static_cast<char>(ck_b);
  return f;
}

FrameAt ParseFrameAt(std::string_view bytes, std::size_t max_payload) {
  FrameAt f;
  if (bytes.size() < 6) return f;
  f.cls = static_cast<std::uint8_t>(bytes[2]);
  f.id = static_cast<std::uint8_t>(bytes[3]);
  f.payload_length = LeRead<std::uint16_t>(bytes, 4);
  if (f.payload_length > max_payload) {
    f.status = FrameAtStatus::kTooLong;
  } else if (bytes.size() < f.frame_size()) {
    f.status = FrameAtStatus::kCut;
  } else {
    const auto [ck_a, ck_b] = Checksum(bytes.substr(2, 4 + f.payload_length));
    const bool ok = static_cast<std::uint8_t>(bytes[6 + f.payload_length]) == ck_a &&
                    static_cast<std::uint8_t>(bytes[7 + f.payload_length]) == ck_b;
    f.status = ok ? FrameAtStatus::kFrame : FrameAtStatus::kBadChecksum;
    if (ok) f.payload = bytes.substr(6, f.payload_length);
  }
  return f;
}

std::vector<InputMessage> InputParser::Feed(std::string_view bytes) {
  std::vector<InputMessage> out;
  for (char c : bytes) FeedByte(static_cast<std::uint8_t>(c), out);
  return out;
}

void InputParser::FeedByte(std::uint8_t b, std::vector<InputMessage>& out) {
  switch (state_) {
    case State::kIdle:
      if (b == kSync1) {
        state_ = State::kSecondSync;
      } else if (b == '$') {
        buf_.clear();
        state_ = State::kNmea;
      }
      return;
    case State::kSecondSync:
      if (b == kSync2) {
        buf_.clear();
        state_ = State::kHeader;
      } else {
        state_ = b == kSync1 ? State::kSecondSync : State::kIdle;
      }
      return;
    case State::kHeader:
      buf_ += static_cast<char>(b);
      if (buf_.size() == 4) {
        const std::size_t len = static_cast<std::uint8_t>(buf_[2]) |
                                (static_cast<std::size_t>(static_cast<std::uint8_t>(buf_[3])) << 8);
        if (len > kMaxInputPayload) {
          ++discarded_;
          state_ = State::kIdle;
          return;
        }
        need_ = len + 2;
        state_ = State::kPayload;
      }
      return;
    case State::kPayload: {
      buf_ += static_cast<char>(b);
      if (--need_ > 0) return;
      state_ = State::kIdle;
      const std::string_view body = std::string_view(buf_).substr(0, buf_.size() - 2);
      const auto [ck_a, ck_b] = Checksum(body);
      if (static_cast<std::uint8_t>(buf_[buf_.size() - 2]) != ck_a ||
          static_cast<std::uint8_t>(buf_.back()) != ck_b) {
        ++discarded_;
        return;
      }
      InputMessage m;
      m.kind = InputMessage::Kind::kUbx;
      m.cls = static_cast<std::uint8_t>(buf_[0]);
      m.id = static_cast<std::uint8_t>(buf_[1]);
      m.payload.assign(buf_.begin() + 4, buf_.end() - 2);
      out.push_back(std::move(m));
      return;
    }
    case State::kNmea:
      if (b == '\n' || b == '\r') {
        state_ = State::kIdle;
        const std::size_t star = buf_.rfind('*');
        if (star == std::string::npos || star + 3 != buf_.size()) {
          ++discarded_;
          return;
        }
        const int h = HexDigit(buf_[star + 1]), l = HexDigit(buf_[star + 2]);
        const std::string body = buf_.substr(0, star);
        if (h < 0 || l < 0 || nmea::Checksum(body) != h * 16 + l) {
          ++discarded_;
          return;
        }
        InputMessage m;
        m.kind = InputMessage::Kind::kNmea;
        m.sentence = body;
        out.push_back(std::move(m));
      } else if (b == '$') {
        ++discarded_;
        buf_.clear();
      } else if (b == kSync1 || buf_.size() > 120) {
        ++discarded_;
        state_ = b == kSync1 ? State::kSecondSync : State::kIdle;
      } else {
        buf_ += static_cast<char>(b);
      }
      return;
  }
}

}  // namespace hil::gnss::ubx

#include "hil/firmware_emu/rtk/rtcm3_stream.h"

#include "hil/firmware_emu/rtk/rtcm3_frame.h"

namespace hil::rtcm3 {
namespace {

unsigned Byte(std::string_view s, std::size_t k) { return static_cast<unsigned char>(s[k]); }

}  // namespace

int ReceivedFrame::message_number() const { return MessageNumber(body); }

int ReceivedFrame::station_id() const {
  if (body.size() < 3) return 0;
  return static_cast<int>(((Byte(body, 1) & 0x0FU) << 8) | Byte(body, 2));
}

void StreamParser::Feed(char byte, std::vector<ReceivedFrame>& out) {
  const auto b = static_cast<unsigned char>(byte);
  if (buf_.empty()) {
    if (b != kPreamble) {
      ++skipped_;
      return;
    }
    buf_.push_back(byte);
    need_ = 3;
    return;
  }
  buf_.push_back(byte);
  if (buf_.size() == 2 && (b & 0xFCU) != 0) {  // the 6 reserved bits must be 0: not a frame
    buf_.clear();
    ++skipped_;
    Feed(byte, out);
    return;
  }
  if (buf_.size() == 3) need_ = 3 + (((Byte(buf_, 1) & 0x03U) << 8) | b) + 3;
  if (buf_.size() == need_) Complete(out);
}

void StreamParser::Complete(std::vector<ReceivedFrame>& out) {
  const std::size_t len = need_ - 6;
  const std::uint32_t crc =
      (Byte(buf_, need_ - 3) << 16) | (Byte(buf_, need_ - 2) << 8) | Byte(buf_, need_ - 1);
  const bool failed = Crc24q(std::string_view(buf_).substr(0, 3 + len)) != crc;
  out.push_back({buf_.substr(3, len), failed});
  const std::string rest = failed ? buf_.substr(1) : std::string();
  buf_.clear();
  need_ = 0;
  if (!failed) return;
  ++skipped_;
  for (const char c : rest) Feed(c, out);  // resynchronise after the failed preamble
}

}  // namespace hil::rtcm3

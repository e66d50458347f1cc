#include "hil/estimator/guidance/slcan_codec.h"

namespace hil::estimator::guidance {
namespace {

constexpr std::array<int, 9> kTable{10000,  20000,  50000,  100000, 125000,
                                    250000, 500000, 800000, 1000000};

char Nibble(std::uint32_t v) {
  v &= 0xF;
  return static_cast<char>(v < 10 ? '0' + v : 'A' + (v - 10));
}

int Digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return 10 + (c - 'a');
  if (c >= 'A' && c <= 'F') return 10 + (c - 'A');
  return -1;
}

void Push(SlcanRecord& r, char c) {
  if (r.size < r.bytes.size()) r.bytes[r.size++] = c;
}

SlcanRecord Single(char c) {
  SlcanRecord r;
  Push(r, c);
  Push(r, '\r');
  return r;
}

}  // namespace

bool FormatSlcanBitrate(int bitrate_bps, SlcanRecord& out) {
  for (std::size_t i = 0; i < kTable.size(); ++i) {
    if (kTable[i] != bitrate_bps) continue;
    out = SlcanRecord{};
    Push(out, 'S');
    Push(out, static_cast<char>('0' + i));
    Push(out, '\r');
    return true;
  }
  return false;
}

SlcanRecord FormatSlcanOpen() { return Single('O'); }
SlcanRecord FormatSlcanClose() { return Single('C'); }

SlcanRecord FormatSlcanExtendedFrame(const IsobusFrame& frame) {
  SlcanRecord r;
  Push(r, 'T');
  for (int shift = 28; shift >= 0; shift -= 4) Push(r, Nibble(frame.id >> shift));
  const std::size_t n = frame.len > 8 ? 8 : frame.len;
  Push(r, static_cast<char>('0' + n));
  for (std::size_t i = 0; i < n; ++i) {
    Push(r, Nibble(frame.data[i] >> 4));
    Push(r, Nibble(frame.data[i]));
  }
  Push(r, '\r');
  return r;
}

SlcanReply SlcanReader::Feed(char byte) {
  if (byte == '\a') {
    size_ = 0;
    overflow_ = false;
    return SlcanReply::kRefused;
  }
  if (byte == '\n') return SlcanReply::kNone;
  if (byte != '\r') {
    if (size_ < buf_.size()) {
      buf_[size_++] = byte;
    } else {
      overflow_ = true;
    }
    return SlcanReply::kNone;
  }
  const SlcanReply r = overflow_ ? SlcanReply::kMalformed : Finish();
  if (r == SlcanReply::kMalformed) ++malformed_;
  size_ = 0;
  overflow_ = false;
  return r;
}

SlcanReply SlcanReader::Finish() {
  if (size_ == 0) return SlcanReply::kAck;
  const char k = buf_[0];
  if ((k == 'z' || k == 'Z') && size_ == 1) return SlcanReply::kTransmitted;
  if (k == 't' || k == 'r' || k == 'R') return SlcanReply::kOtherFrame;
  if (k != 'T' || size_ < 10) return SlcanReply::kMalformed;
  std::uint32_t id = 0;
  for (std::size_t i = 1; i <= 8; ++i) {
    const int d = Digit(buf_[i]);
    if (d < 0) return SlcanReply::kMalformed;
    id = (id << 4) | static_cast<std::uint32_t>(d);
  }
  const int n = buf_[9] - '0';
  if (n < 0 || n > 8 || id > 0x1FFFFFFFU) return SlcanReply::kMalformed;
  const std::size_t need = 10 + 2 * static_cast<std::size_t>(n);
  if (size_ != need && size_ != need + 4) return SlcanReply::kMalformed;  // + a time stamp
  IsobusFrame f;
  f.id = id;
  f.len = static_cast<std::uint8_t>(n);
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
    const int hi = Digit(buf_[10 + 2 * i]), lo = Digit(buf_[11 + 2 * i]);
    if (hi < 0 || lo < 0) return SlcanReply::kMalformed;
    f.data[i] = static_cast<std::uint8_t>((hi << 4) | lo);
  }
  frame_ = f;
  return SlcanReply::kFrame;
}

}  // namespace hil::estimator::guidance

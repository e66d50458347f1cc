#include "hil/estimator/drivers/benewake_decoder.h"

#include <algorithm>
#include <cstring>

#include "hil/estimator/drivers/little_endian.h"

namespace hil::estimator::drivers {
namespace {

constexpr unsigned char kData = 0x59, kReply = 0x5A;
constexpr std::uint8_t kFormatId = 0x05, kFormatMm = 0x06, kFormatCm = 0x01;

std::uint8_t SumOf(const unsigned char* p, std::size_t n) {
  unsigned s = 0;
  for (std::size_t k = 0; k < n; ++k) s += p[k];
  return static_cast<std::uint8_t>(s & 0xFFu);
}

}  // namespace

int BenewakeDecoder::FrameLength() const {
  if (buf_[0] == kData) {
    if (len_ < 2) return 0;
    return buf_[1] == kData ? 9 : -1;
  }
  if (buf_[0] == kReply) {
    if (len_ < 2) return 0;
    const std::size_t n = buf_[1];
    return n >= 4 && n <= kMax ? static_cast<int>(n) : -1;
  }
  return -1;
}

void BenewakeDecoder::Feed(std::string_view bytes) {
  for (const char c : bytes) {
    buf_[len_++] = static_cast<unsigned char>(c);
    ++stream_bytes_;
    while (len_ > 0) {
      const int n = FrameLength();
      if (n == 0 || (n > 0 && len_ < static_cast<std::size_t>(n))) break;
      std::size_t drop = 1;
      if (n < 0) {
        ++stats_.garbage_bytes;
      } else if (SumOf(buf_.data(), static_cast<std::size_t>(n) - 1) != buf_[n - 1]) {
        ++stats_.bad_checksum;
      } else {
        frame_end_bytes_ = stream_bytes_ - (len_ - static_cast<std::size_t>(n));
        Emit(static_cast<std::size_t>(n));
        drop = static_cast<std::size_t>(n);
      }
      std::memmove(buf_.data(), buf_.data() + drop, len_ - drop);
      len_ -= drop;
    }
  }
}

void BenewakeDecoder::Emit(std::size_t len) {
  if (buf_[0] == kReply) {
    BenewakeReply r;
    r.id = buf_[2];
    r.payload_size = len - 4;
    std::copy_n(buf_.begin() + 3, r.payload_size, r.payload.begin());
    if (r.id == kFormatId && r.payload_size == 1) {
      if (r.payload[0] == kFormatMm) unit_ = BenewakeUnit::kMm;
      if (r.payload[0] == kFormatCm) unit_ = BenewakeUnit::kCm;
    }
    ++stats_.replies;
    if (on_reply_) on_reply_(r);
    return;
  }
  BenewakeRange r;
  r.dist_raw = LeU16(&buf_[2]);
  r.amp = LeU16(&buf_[4]);
  r.temp_raw = LeU16(&buf_[6]);
  r.temperature_c = r.temp_raw / 8.0 - 256.0;
  if (model_ == BenewakeModel::kTfLuna) {
    r.valid = r.dist_raw != 0 && r.amp >= 100 && r.amp != 0xFFFF;
  } else {
    r.valid = r.dist_raw < 0xFFFC && r.amp >= 100 && r.amp != 0xFFFF;
  }
  if (r.valid) r.distance_m = r.dist_raw * (unit_ == BenewakeUnit::kMm ? 0.001 : 0.01);
  ++stats_.ranges;
  if (!r.valid) ++stats_.invalid_ranges;
  on_range_(r);
}

}  // namespace hil::estimator::drivers

#include "hil/estimator/drivers/uwb_tdoa_decoder.h"

#include <cstring>

#include "hil/estimator/drivers/little_endian.h"

namespace hil::estimator::drivers {
namespace {

constexpr unsigned char kHeader = 0x55, kMark = 0xD7;
constexpr double kFrameSpeedOfLight_mps = 3.0e8;

}  // namespace

void UwbTdoaDecoder::Feed(std::string_view bytes) {
  for (char c : bytes) {
    buf_[len_++] = static_cast<unsigned char>(c);
    if (len_ == buf_.size()) Scan();
  }
  Scan();
}

void UwbTdoaDecoder::Scan() {
  std::size_t i = 0;
  while (i < len_) {
    const std::size_t n = len_ - i;
    if (buf_[i] != kHeader || (n >= 2 && buf_[i + 1] != kMark)) {
      ++stats_.garbage_bytes;
      ++i;
      continue;
    }
    if (n < kFrame) break;
    const unsigned char* p = &buf_[i];
    unsigned sum = 0;
    for (std::size_t k = 0; k < kFrame - 1; ++k) sum += p[k];
    if ((sum & 0xFFu) != p[kFrame - 1]) {
      ++stats_.bad_checksum;
      ++i;
      continue;
    }
    if (p[3] != 3) {
      ++stats_.bad_count;
      ++i;
      continue;
    }
    UwbTdoaSample s;
    s.id = p[2];
    s.system_time_ms = LeU32(p + 4);
    for (std::size_t k = 0; k < 3; ++k) {
      s.t_i1_ps[k] = static_cast<std::int32_t>(LeU32(p + 8 + 4 * k));
      s.r_i1_m[static_cast<Eigen::Index>(k)] =
          kFrameSpeedOfLight_mps * static_cast<double>(s.t_i1_ps[k]) * 1e-12;
    }
    ++stats_.frames_ok;
    if (handler_) handler_(s);
    i += kFrame;
  }
  if (i > 0) {
    std::memmove(buf_.data(), buf_.data() + i, len_ - i);
    len_ -= i;
  }
}

}  // namespace hil::estimator::drivers

#include "hil/estimator/drivers/linktrack_decoder.h"

#include <bit>
#include <cstring>

namespace hil::estimator::drivers {
namespace {

std::uint32_t Le(const unsigned char* p, int n) {
  std::uint32_t v = 0;
  for (int k = n - 1; k >= 0; --k) v = (v << 8) | p[k];
  return v;
}
double Int24(const unsigned char* p) {
  std::int32_t v = static_cast<std::int32_t>(Le(p, 3));
  if (v & 0x800000) v -= 0x1000000;  // sign-extend byte 2
  return static_cast<double>(v);
}
double Float32(const unsigned char* p) { return std::bit_cast<float>(Le(p, 4)); }

}  // namespace

void LinkTrackDecoder::Feed(std::string_view bytes) {
  for (char c : bytes) {
    buf_[len_++] = static_cast<unsigned char>(c);
    if (len_ == buf_.size()) Scan();
  }
  Scan();
}

void LinkTrackDecoder::Scan() {
  std::size_t i = 0;
  while (i < len_) {
    const std::size_t n = len_ - i;
    if (buf_[i] != 0x55 || (n >= 2 && buf_[i + 1] != 0x01)) {
      ++stats_.garbage_bytes;
      ++i;
      continue;
    }
    if (n < kFrame) break;
    unsigned sum = 0;
    for (std::size_t k = 0; k < kFrame - 1; ++k) sum += buf_[i + k];
    if ((sum & 0xFFu) != buf_[i + kFrame - 1]) {
      ++stats_.bad_checksum;
      ++i;
      continue;
    }
    Emit(&buf_[i]);
    i += kFrame;
  }
  if (i > 0) {
    std::memmove(buf_.data(), buf_.data() + i, len_ - i);
    len_ -= i;
  }
}

void LinkTrackDecoder::Emit(const unsigned char* p) {
  LinkTrackTagFrame f;
  f.id = p[2];
  f.role = p[3];
  for (int k = 0; k < 3; ++k) {
    f.p_m[k] = Int24(p + 4 + 3 * k) / 1000.0;
    f.v_mps[k] = Int24(p + 13 + 3 * k) / 10000.0;
    f.gyro_radps[k] = Float32(p + 46 + 4 * k);
    f.acc_mps2[k] = Float32(p + 58 + 4 * k);
    f.angle_deg[k] = static_cast<std::int16_t>(Le(p + 82 + 2 * k, 2)) / 100.0;
    f.eop_m[k] = p[117 + k] / 100.0;
  }
  for (int k = 0; k < 8; ++k) f.dis_m[k] = Int24(p + 22 + 3 * k) / 1000.0;
  for (int k = 0; k < 4; ++k) f.quat_wxyz[k] = Float32(p + 88 + 4 * k);
  f.local_time_ms = Le(p + 108, 4);
  f.system_time_ms = Le(p + 112, 4);
  f.voltage_v = Le(p + 120, 2) / 1000.0;
  ++stats_.frames_ok;
  if (handler_) handler_(f);
}

}  // namespace hil::estimator::drivers

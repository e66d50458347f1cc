#include "hil/estimator/drivers/wt901c_decoder.h"

#include <cstring>

#include "hil/estimator/drivers/little_endian.h"

namespace hil::estimator::drivers {
namespace {

bool CanStart(const unsigned char* p, std::size_t n) {
  return p[0] == 0x55 && (n < 2 || (p[1] >= 0x50 && p[1] <= 0x5F));
}

}  // namespace

void Wt901cDecoder::Feed(std::string_view bytes) {
  for (char c : bytes) {
    buf_[len_++] = static_cast<unsigned char>(c);
    if (len_ == buf_.size()) Scan();
  }
  Scan();
}

void Wt901cDecoder::Scan() {
  std::size_t i = 0;
  while (i < len_) {
    if (!CanStart(&buf_[i], len_ - i)) {
      ++stats_.garbage_bytes;
      ++i;
      continue;
    }
    if (len_ - i < kPacket) break;
    unsigned sum = 0;
    for (std::size_t k = 0; k < kPacket - 1; ++k) sum += buf_[i + k];
    if ((sum & 0xFFu) != buf_[i + kPacket - 1]) {
      ++stats_.bad_checksum;
      ++i;  // resynchronise one byte after this header
      continue;
    }
    Emit(&buf_[i]);
    i += kPacket;
  }
  if (i > 0) {
    std::memmove(buf_.data(), buf_.data() + i, len_ - i);
    len_ -= i;
  }
}

void Wt901cDecoder::Emit(const unsigned char* p) {
  WitPacket w;
  w.type = p[1];
  for (int k = 0; k < 4; ++k) w.raw[k] = LeI16(p + 2 + 2 * k);
  const Eigen::Vector3d v(w.raw[0], w.raw[1], w.raw[2]);
  const double t_c = w.raw[3] / 100.0;
  switch (w.type) {
    case 0x51:
      w.accel_g = v / 32768.0 * 16.0, w.temperature_c = t_c, ++stats_.acc;
      break;
    case 0x52:
      w.rate_dps = v / 32768.0 * 2000.0, w.temperature_c = t_c, ++stats_.rate;
      break;
    case 0x53:
      w.angle_deg = v / 32768.0 * 180.0;
      w.version = static_cast<std::uint16_t>(w.raw[3]);
      ++stats_.angle;
      break;
    case 0x54:
      w.mag_counts = v, w.temperature_c = t_c, ++stats_.mag;
      break;
    case 0x5F:
      for (int k = 0; k < 4; ++k) w.registers[k] = static_cast<std::uint16_t>(w.raw[k]);
      ++stats_.register_reads;
      break;
    default:
      ++stats_.other_types;
  }
  ++stats_.packets_ok;
  if (handler_) handler_(w);
}

}  // namespace hil::estimator::drivers

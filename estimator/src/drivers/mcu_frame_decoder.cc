#include "hil/estimator/drivers/mcu_frame_decoder.h"

#include <bit>
#include <cstring>

namespace hil::estimator::drivers {
namespace {

std::uint8_t U8(const char* p) { return static_cast<std::uint8_t>(*p); }
std::uint16_t U16(const char* p) { return static_cast<std::uint16_t>(U8(p) | (U8(p + 1) << 8)); }
std::int16_t I16(const char* p) { return static_cast<std::int16_t>(U16(p)); }
std::uint32_t U32(const char* p) {
  return static_cast<std::uint32_t>(U8(p)) | (static_cast<std::uint32_t>(U8(p + 1)) << 8) |
         (static_cast<std::uint32_t>(U8(p + 2)) << 16) |
         (static_cast<std::uint32_t>(U8(p + 3)) << 24);
}
float F32(const char* p) { return std::bit_cast<float>(U32(p)); }

int PayloadLength(std::uint8_t type) {
  switch (type) {
    case 1:
      return 12;
    case 2:
      return 6;
    case 3:
      return 7;
    case 4:
      return 26;
    default:
      return -1;
  }
}

}  // namespace

std::uint16_t Crc16CcittFalse(std::string_view bytes) {
  std::uint16_t crc = 0xFFFF;
  for (char c : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ (static_cast<std::uint8_t>(c) << 8));
    for (int i = 0; i < 8; ++i) {
      crc = static_cast<std::uint16_t>((crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1);
    }
  }
  return crc;
}

void McuFrameDecoder::Feed(std::string_view bytes) {
  for (char c : bytes) {
    if (len_ == buf_.size()) {
      // cannot happen with the scan below; keep the invariant anyway
      std::memmove(buf_.data(), buf_.data() + 1, --len_);
      ++stats_.garbage_bytes;
    }
    buf_[len_++] = c;
    Scan();
  }
}

void McuFrameDecoder::Scan() {
  for (;;) {
    // drop bytes up to a sync pair
    std::size_t i = 0;
    while (i < len_ && !(U8(&buf_[i]) == 0xA5 && (i + 1 == len_ || U8(&buf_[i + 1]) == 0x5A))) ++i;
    if (i > 0) {
      stats_.garbage_bytes += i;
      std::memmove(buf_.data(), buf_.data() + i, len_ - i);
      len_ -= i;
    }
    if (len_ < 5) return;
    const int n = PayloadLength(U8(&buf_[3]));
    if (U8(&buf_[2]) != 0x01 || n < 0 || U8(&buf_[4]) != n) {
      ++stats_.bad_header;
      std::memmove(buf_.data(), buf_.data() + 1, --len_);
      continue;
    }
    const std::size_t total = static_cast<std::size_t>(n) + 13;
    if (len_ < total) return;
    const char* f = buf_.data();
    const std::uint16_t crc =
        Crc16CcittFalse(std::string_view(f + 2, static_cast<std::size_t>(n) + 9));
    if (crc != U16(f + 11 + n)) {
      ++stats_.bad_crc;
      std::memmove(buf_.data(), buf_.data() + 1, --len_);
      continue;
    }
    McuFrame fr;
    fr.type = static_cast<McuFrame::Type>(U8(f + 3));
    fr.sequence = U16(f + 5);
    fr.tick = U32(f + 7);
    const char* p = f + 11;
    switch (fr.type) {
      case McuFrame::Type::kImu:
        for (int k = 0; k < 3; ++k) {
          fr.accel_raw[k] = I16(p + 2 * k);
          fr.gyro_raw[k] = I16(p + 6 + 2 * k);
        }
        break;
      case McuFrame::Type::kMag:
        for (int k = 0; k < 3; ++k) fr.mag_raw[k] = I16(p + 2 * k);
        break;
      case McuFrame::Type::kTimePulse:
        fr.gps_week = U16(p);
        fr.tow_ms = U32(p + 2);
        fr.time_valid = (U8(p + 6) & 1) != 0;
        break;
      case McuFrame::Type::kStatus:
        fr.reset_cause = U8(p);
        fr.status_flags = U8(p + 1);
        fr.reset_count = U16(p + 2);
        fr.nominal_tick_hz = U32(p + 4);
        fr.nominal_imu_period_ticks = U32(p + 8);
        fr.accel_scale_mps2_per_lsb = F32(p + 12);
        fr.gyro_scale_radps_per_lsb = F32(p + 16);
        fr.mag_scale_uT_per_lsb = F32(p + 20);
        fr.profile = U8(p + 24);
        break;
    }
    if (have_seq_ && fr.sequence != static_cast<std::uint16_t>(last_seq_ + 1) && fr.sequence != 0)
      ++stats_.sequence_gaps;
    have_seq_ = true;
    last_seq_ = fr.sequence;
    ++stats_.frames_ok;
    std::memmove(buf_.data(), buf_.data() + total, len_ - total);
    len_ -= total;
    if (handler_) handler_(fr);
  }
}

}  // namespace hil::estimator::drivers

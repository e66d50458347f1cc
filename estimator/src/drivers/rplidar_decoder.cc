#include "hil/estimator/drivers/rplidar_decoder.h"

#include <algorithm>
#include <cstring>

#include "hil/estimator/drivers/little_endian.h"

namespace hil::estimator::drivers {
namespace {

constexpr std::size_t kDesc = 7, kNode = 5, kCap = 84;

// The descriptors a host may meet: (length, multiple, type).
bool KnownDescriptor(std::uint32_t len, bool multiple, std::uint8_t type) {
  switch (type) {
    case 0x04:
      return len == 20 && !multiple;
    case 0x06:
      return len == 3 && !multiple;
    case 0x15:
      return len == 4 && !multiple;
    case 0xFF:
      return len == 4 && !multiple;
    case 0x81:
      return len == 5 && multiple;
    case 0x82:
      return len == 84 && multiple;
    default:
      return false;
  }
}

}  // namespace

void RplidarDecoder::Feed(std::string_view bytes) {
  for (const char c : bytes) {
    buf_[len_++] = static_cast<unsigned char>(c);
    while (len_ > 0 && Step()) {
    }
  }
}

void RplidarDecoder::Drop(std::size_t n) {
  std::memmove(buf_.data(), buf_.data() + n, len_ - n);
  len_ -= n;
}

bool RplidarDecoder::TryDescriptor() {
  if (len_ < 2 || buf_[0] != 0xA5 || buf_[1] != 0x5A || len_ < kDesc) return false;
  const std::uint32_t word = LeU32(&buf_[2]);
  const std::uint32_t length = word & 0x3FFFFFFFu;
  const bool multiple = (word >> 30) == 1;
  if (!KnownDescriptor(length, multiple, buf_[6])) {
    if (buf_[6] != 0x04 && buf_[6] != 0x06 && buf_[6] != 0x15 && buf_[6] != 0x81 &&
        buf_[6] != 0x82 && buf_[6] != 0xFF)
      ++stats_.unknown_types;
    return false;
  }
  type_ = buf_[6];
  ++stats_.descriptors;
  state_ = type_ == 0x81 ? State::kNodes : type_ == 0x82 ? State::kCapsules : State::kSingle;
  single_len_ = length;
  have_prev_ = false;
  Drop(kDesc);
  return true;
}

bool RplidarDecoder::Step() {
  // a descriptor can start where a response may, and between nodes (A5 5A is never a valid
  // node: its check bit C is 0); inside a single response's data it is data
  const bool between = state_ == State::kIdle || state_ == State::kNodes;
  if (between && buf_[0] == 0xA5 && (len_ < 2 || buf_[1] == 0x5A)) {
    if (len_ < kDesc) return false;
    if (TryDescriptor()) return true;
  }
  switch (state_) {
    case State::kIdle:
      ++stats_.garbage_bytes;
      Drop(1);
      return true;
    case State::kSingle:
      if (len_ < single_len_) return false;
      Single();
      return true;
    case State::kNodes:
      return Node();
    case State::kCapsules:
      return Capsule();
  }
  return false;
}

void RplidarDecoder::Single() {
  LidarSingleResponse r;
  r.type = type_;
  const unsigned char* p = buf_.data();
  if (type_ == 0x04) {
    r.info.model = p[0], r.info.firmware_minor = p[1], r.info.firmware_major = p[2];
    r.info.hardware = p[3];
    std::copy_n(p + 4, 16, r.info.serial.begin());
  } else if (type_ == 0x06) {
    r.health_status = p[0], r.health_error = LeU16(p + 1);
  } else if (type_ == 0x15) {
    r.standard_us = LeU16(p), r.express_us = LeU16(p + 2);
  } else {
    r.acc_board_flag = LeU32(p);
  }
  ++stats_.responses;
  Drop(single_len_);
  state_ = State::kIdle;
  if (on_response_) on_response_(r);
}

bool RplidarDecoder::Node() {
  if (len_ < kNode) return false;
  const unsigned s = buf_[0] & 1u, not_s = (buf_[0] >> 1) & 1u;
  if (s == not_s || (buf_[1] & 1u) == 0) {
    ++stats_.bad_nodes;
    Drop(1);
    return true;
  }
  LidarPoint p;
  p.quality = static_cast<std::uint8_t>(buf_[0] >> 2);
  p.start = s == 1;
  p.angle_deg = (LeU16(&buf_[1]) >> 1) / 64.0;
  p.distance_m = LeU16(&buf_[3]) / 4000.0;
  ++stats_.nodes;
  Drop(kNode);
  on_point_(p);
  return true;
}

bool RplidarDecoder::Capsule() {
  if ((buf_[0] >> 4) != 0xA || (len_ >= 2 && (buf_[1] >> 4) != 0x5)) {
    ++stats_.garbage_bytes;  // cannot start a capsule (e.g. the banner after RESET)
    Drop(1);
    return true;
  }
  if (len_ < kCap) {
    // a descriptor (a new request's answer) may replace the capsule stream
    if (len_ >= kDesc && buf_[0] == 0xA5 && buf_[1] == 0x5A && TryDescriptor()) return true;
    return false;
  }
  unsigned cs = 0;
  for (std::size_t k = 2; k < kCap; ++k) cs ^= buf_[k];
  const bool sync = (buf_[0] >> 4) == 0xA && (buf_[1] >> 4) == 0x5;
  const bool sum_ok = (buf_[0] & 0x0Fu) == (cs & 0x0Fu) && (buf_[1] & 0x0Fu) == (cs >> 4);
  if (!sync || !sum_ok) {
    if (TryDescriptor()) return true;
    ++stats_.bad_capsules;
    Drop(1);
    return true;
  }
  const std::uint16_t start = LeU16(&buf_[2]);
  if (start & 0x8000u) have_prev_ = false;  // a new scan: no previous capsule to pair with
  if (have_prev_) EmitCapsule(start & 0x7FFFu);
  std::copy_n(buf_.begin(), kCap, prev_capsule_.begin());
  have_prev_ = true;
  ++stats_.capsules;
  Drop(kCap);
  return true;
}

void RplidarDecoder::EmitCapsule(std::uint16_t next_start_q6) {
  const unsigned char* c = prev_capsule_.data();
  const double a0 = (LeU16(c + 2) & 0x7FFFu) / 64.0;
  double diff = next_start_q6 / 64.0 - a0;
  if (diff < 0) diff += 360.0;
  for (std::size_t k = 0; k < 32; ++k) {
    const unsigned char* cabin = c + 4 + 5 * (k / 2);
    const std::uint16_t word = LeU16(cabin + 2 * (k % 2));
    // the 6-bit signed q3 offset: low 4 bits in the offsets byte, top 2 in the distance word
    const unsigned nibble = (k % 2 == 0) ? (cabin[4] & 0x0Fu) : (cabin[4] >> 4);
    int offset_q3 = static_cast<int>(nibble | ((word & 0x3u) << 4));
    if (offset_q3 & 0x20) offset_q3 -= 64;
    LidarPoint p;
    p.express = true;
    p.distance_m = (word >> 2) / 1000.0;
    p.quality = p.distance_m > 0 ? 47 : 0;
    double a = a0 + diff * static_cast<double>(k) / 32.0 - offset_q3 / 8.0;
    a -= 360.0 * static_cast<double>(static_cast<int>(a / 360.0));
    if (a < 0) a += 360.0;
    p.angle_deg = a;
    p.start = a < prev_angle_deg_;
    prev_angle_deg_ = a;
    on_point_(p);
  }
}

}  // namespace hil::estimator::drivers

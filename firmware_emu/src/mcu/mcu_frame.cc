#include "hil/firmware_emu/mcu/mcu_frame.h"

#include <bit>
#include <stdexcept>
#include <vector>

namespace hil::mcu {
namespace {

void PutU8(std::vector<std::uint8_t>& b, std::uint8_t v) { b.push_back(v); }
void PutU16(std::vector<std::uint8_t>& b, std::uint16_t v) {
  b.push_back(static_cast<std::uint8_t>(v & 0xFF));
  b.push_back(static_cast<std::uint8_t>(v >> 8));
}
void PutI16(std::vector<std::uint8_t>& b, std::int16_t v) {
  PutU16(b, static_cast<std::uint16_t>(v));
}
void PutU32(std::vector<std::uint8_t>& b, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>((v >> (8 * i)) & 0xFF));
}
void PutF32(std::vector<std::uint8_t>& b, float v) { PutU32(b, std::bit_cast<std::uint32_t>(v)); }

}  // namespace

std::uint16_t Crc16CcittFalse(std::span<const std::uint8_t> bytes) {
  std::uint16_t crc = 0xFFFF;
  for (std::uint8_t byte : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ (byte << 8));
    for (int k = 0; k < 8; ++k)
      crc = (crc & 0x8000) ? static_cast<std::uint16_t>((crc << 1) ^ 0x1021)
                           : static_cast<std::uint16_t>(crc << 1);
  }
  return crc;
}

std::string EncodeFrame(MessageType type, std::uint16_t sequence, std::uint32_t tick,
                        std::span<const std::uint8_t> payload) {
  if (payload.size() > 255) throw std::invalid_argument("MCU frame payload longer than 255 bytes");
  std::vector<std::uint8_t> body;
  body.reserve(kHeaderBytes + payload.size());
  PutU8(body, kProtocolVersion);
  PutU8(body, static_cast<std::uint8_t>(type));
  PutU8(body, static_cast<std::uint8_t>(payload.size()));
  PutU16(body, sequence);
  PutU32(body, tick);
  body.insert(body.end(), payload.begin(), payload.end());
  const std::uint16_t crc = Crc16CcittFalse(body);
  PutU16(body, crc);
  std::string out;
  out.reserve(body.size() + 2);
  out.push_back(static_cast<char>(kSync1));
  out.push_back(static_cast<char>(kSync2));
  for (std::uint8_t b : body) out.push_back(static_cast<char>(b));
  return out;
}

std::string EncodeImuSample(std::uint16_t sequence, std::uint32_t tick, const ImuSamplePayload& p) {
  std::vector<std::uint8_t> b;
  for (std::int16_t v : p.accel) PutI16(b, v);
  for (std::int16_t v : p.gyro) PutI16(b, v);
  return EncodeFrame(MessageType::kImuSample, sequence, tick, b);
}

std::string EncodeMagSample(std::uint16_t sequence, std::uint32_t tick, const MagSamplePayload& p) {
  std::vector<std::uint8_t> b;
  for (std::int16_t v : p.mag) PutI16(b, v);
  return EncodeFrame(MessageType::kMagSample, sequence, tick, b);
}

std::string EncodeTimePulse(std::uint16_t sequence, std::uint32_t latched_tick,
                            const TimePulsePayload& p) {
  std::vector<std::uint8_t> b;
  PutU16(b, p.gps_week);
  PutU32(b, p.tow_ms);
  PutU8(b, p.time_valid ? 1 : 0);
  return EncodeFrame(MessageType::kTimePulse, sequence, latched_tick, b);
}

std::string EncodeStatus(std::uint16_t sequence, std::uint32_t tick, const StatusPayload& p) {
  std::vector<std::uint8_t> b;
  PutU8(b, p.reset_cause);
  PutU8(b, p.pulse_seen ? 1 : 0);
  PutU16(b, p.reset_count);
  PutU32(b, p.tick_hz);
  PutU32(b, p.imu_period_ticks);
  PutF32(b, p.accel_scale_mps2_per_lsb);
  PutF32(b, p.gyro_scale_radps_per_lsb);
  PutF32(b, p.mag_scale_uT_per_lsb);
  PutU8(b, p.profile);
  PutU8(b, 0);
  return EncodeFrame(MessageType::kStatus, sequence, tick, b);
}

}  // namespace hil::mcu

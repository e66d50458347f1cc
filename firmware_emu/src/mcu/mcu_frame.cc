#include "hil/firmware_emu/mcu/mcu_frame.h"

#include <bit>
#include <stdexcept>
#include <vector>

#include "hil/firmware_emu/little_endian.h"

namespace hil::mcu {
namespace {

void PutU8(std::vector<std::uint8_t>& b, std::uint8_t v) { b.push_back(v); }
void PutF32(std::vector<std::uint8_t>& b, float v) {
  LeAppend(b, std::bit_cast<std::uint32_t>(v), 4);
}

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
  LeAppend(body, sequence, 2);
  LeAppend(body, tick, 4);
  body.insert(body.end(), payload.begin(), payload.end());
  const std::uint16_t crc = Crc16CcittFalse(body);
  LeAppend(body, crc, 2);
  std::string out;
  out.reserve(body.size() + 2);
  out.push_back(static_cast<char>(kSync1));
  out.push_back(static_cast<char>(kSync2));
  for (std::uint8_t b : body) out.push_back(static_cast<char>(b));
  return out;
}

std::string EncodeImuSample(std::uint16_t sequence, std::uint32_t tick, const ImuSamplePayload& p) {
  std::vector<std::uint8_t> b;
  for (std::int16_t v : p.accel) LeAppend(b, static_cast<std::uint16_t>(v), 2);
  for (std::int16_t v : p.gyro) LeAppend(b, static_cast<std::uint16_t>(v), 2);
  return EncodeFrame(MessageType::kImuSample, sequence, tick, b);
}

std::string EncodeMagSample(std::uint16_t sequence, std::uint32_t tick, const MagSamplePayload& p) {
  std::vector<std::uint8_t> b;
  for (std::int16_t v : p.mag) LeAppend(b, static_cast<std::uint16_t>(v), 2);
  return EncodeFrame(MessageType::kMagSample, sequence, tick, b);
}

std::string EncodeTimePulse(std::uint16_t sequence, std::uint32_t latched_tick,
                            const TimePulsePayload& p) {
  std::vector<std::uint8_t> b;
  LeAppend(b, p.gps_week, 2);
  LeAppend(b, p.tow_ms, 4);
  PutU8(b, p.time_valid ? 1 : 0);
  return EncodeFrame(MessageType::kTimePulse, sequence, latched_tick, b);
}

std::string EncodeStatus(std::uint16_t sequence, std::uint32_t tick, const StatusPayload& p) {
  std::vector<std::uint8_t> b;
  PutU8(b, p.reset_cause);
  PutU8(b, p.pulse_seen ? 1 : 0);
  LeAppend(b, p.reset_count, 2);
  LeAppend(b, p.tick_hz, 4);
  LeAppend(b, p.imu_period_ticks, 4);
  PutF32(b, p.accel_scale_mps2_per_lsb);
  PutF32(b, p.gyro_scale_radps_per_lsb);
  PutF32(b, p.mag_scale_uT_per_lsb);
  PutU8(b, p.profile);
  PutU8(b, 0);
  return EncodeFrame(MessageType::kStatus, sequence, tick, b);
}

}  // namespace hil::mcu

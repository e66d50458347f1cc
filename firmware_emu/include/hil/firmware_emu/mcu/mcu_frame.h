#pragma once
/// @file
/// Encoder of the MCU frame protocol, version 1 (vectors/mcu/mcu_frame_protocol.md): framing
/// (sync, version, type, length, sequence, tick, CRC-16/CCITT-FALSE) and the four payloads.
/// Explicit little-endian byte writes; no struct punning.

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace hil::mcu {

inline constexpr std::uint8_t kSync1 = 0xA5;
inline constexpr std::uint8_t kSync2 = 0x5A;
inline constexpr std::uint8_t kProtocolVersion = 1;
inline constexpr std::size_t kHeaderBytes = 11;
inline constexpr std::size_t kCrcBytes = 2;
inline constexpr std::uint32_t kNominalTickHz = 1000000;

enum class MessageType : std::uint8_t {
  kImuSample = 0x01,
  kMagSample = 0x02,
  kTimePulse = 0x03,
  kStatus = 0x04,
};

/// CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, no final XOR).
std::uint16_t Crc16CcittFalse(std::span<const std::uint8_t> bytes);

/// IMU_SAMPLE payload: accel and gyro in LSB, IMU frame.
struct ImuSamplePayload {
  std::array<std::int16_t, 3> accel{};
  std::array<std::int16_t, 3> gyro{};
};
/// MAG_SAMPLE payload in LSB.
struct MagSamplePayload {
  std::array<std::int16_t, 3> mag{};
};
/// TIME_PULSE payload (the frame's tick is the latched tick).
struct TimePulsePayload {
  std::uint16_t gps_week = 0;
  std::uint32_t tow_ms = 0;
  bool time_valid = false;
};
/// STATUS payload.
struct StatusPayload {
  std::uint8_t reset_cause = 0;  ///< 0 power-on, 1 watchdog, 2 brown-out, 3 external
  bool pulse_seen = false;       ///< a time pulse in the last 1.5 s
  std::uint16_t reset_count = 0;
  std::uint32_t tick_hz = kNominalTickHz;
  std::uint32_t imu_period_ticks = 0;
  float accel_scale_mps2_per_lsb = 0;
  float gyro_scale_radps_per_lsb = 0;
  float mag_scale_uT_per_lsb = 0;
  std::uint8_t profile = 0;
};

/// A complete frame: sync, header, payload, CRC (low byte first).
std::string EncodeFrame(MessageType type, std::uint16_t sequence, std::uint32_t tick,
                        std::span<const std::uint8_t> payload);
std::string EncodeImuSample(std::uint16_t sequence, std::uint32_t tick, const ImuSamplePayload& p);
std::string EncodeMagSample(std::uint16_t sequence, std::uint32_t tick, const MagSamplePayload& p);
std::string EncodeTimePulse(std::uint16_t sequence, std::uint32_t latched_tick,
                            const TimePulsePayload& p);
std::string EncodeStatus(std::uint16_t sequence, std::uint32_t tick, const StatusPayload& p);

}  // namespace hil::mcu

#pragma once
/// @file
/// Tolerant decoder of the microcontroller's binary frame protocol v1
/// (vectors/mcu/mcu_frame_protocol.md): sync A5 5A, version, type, length, u16 sequence, u32 tick,
/// payload, CRC-16/CCITT-FALSE over version..payload, low byte first. Bytes may arrive in any
/// pieces; garbage is skipped; a frame with a bad version, length or CRC is counted and the search
/// restarts one byte after its sync. Never throws on input. An independent implementation from the
/// emulator's encoder (firmware_emu), tied to it by the golden vectors.

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>

namespace hil::estimator::drivers {

/// One decoded frame; the payload fields of its type are filled.
struct McuFrame {
  enum class Type : std::uint8_t {
    kImu = 1,
    kMag = 2,
    kTimePulse = 3,
    kStatus = 4
  } type = Type::kImu;
  std::uint16_t sequence = 0;
  std::uint32_t tick = 0;
  std::array<std::int16_t, 3> accel_raw{}, gyro_raw{}, mag_raw{};
  // TIME_PULSE
  std::uint16_t gps_week = 0;
  std::uint32_t tow_ms = 0;
  bool time_valid = false;
  // STATUS
  std::uint8_t reset_cause = 0, status_flags = 0, profile = 0;
  std::uint16_t reset_count = 0;
  std::uint32_t nominal_tick_hz = 0, nominal_imu_period_ticks = 0;
  float accel_scale_mps2_per_lsb = 0, gyro_scale_radps_per_lsb = 0, mag_scale_uT_per_lsb = 0;
};

struct McuDecoderStats {
  std::uint64_t frames_ok = 0, bad_crc = 0, bad_header = 0, garbage_bytes = 0, sequence_gaps = 0;
};

/// CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, no final XOR).
std::uint16_t Crc16CcittFalse(std::string_view bytes);

class McuFrameDecoder {
 public:
  using Handler = std::function<void(const McuFrame&)>;
  explicit McuFrameDecoder(Handler h) : handler_(std::move(h)) {}
  void Feed(std::string_view bytes);
  const McuDecoderStats& stats() const { return stats_; }

 private:
  void Scan();
  static constexpr std::size_t kMaxFrame = 255 + 13;
  Handler handler_;
  McuDecoderStats stats_;
  std::array<char, 2 * kMaxFrame> buf_{};
  std::size_t len_ = 0;
  bool have_seq_ = false;
  std::uint16_t last_seq_ = 0;
};

}  // namespace hil::estimator::drivers

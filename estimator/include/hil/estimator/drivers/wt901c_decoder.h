#pragma once
/// @file
/// Tolerant decoder of the WitMotion standard protocol (WT901C, seeds_001_003.md §C.1): 11-byte
/// packets `55 TYPE D0..D3 SUM`, SUM = low 8 bits of the sum of bytes 0–9. Bytes may arrive in any
/// pieces; a byte that cannot start a packet (not 0x55, or a type outside 0x50–0x5F) is garbage;
/// a bad sum is counted and the search resumes one byte after the header (as the vendor SDK does).
/// Never throws on input; fixed buffer, no allocation. Independent of the emulator's encoder
/// (firmware_emu/src/attitude), tied to it by vectors/wt901c.

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>

#include <Eigen/Core>

namespace hil::estimator::drivers {

/// One packet with its fields scaled; only the fields of its type are meaningful.
struct WitPacket {
  std::uint8_t type = 0;
  std::array<std::int16_t, 4> raw{};
  Eigen::Vector3d accel_g = Eigen::Vector3d::Zero();     ///< 0x51: raw/32768 × 16 g
  Eigen::Vector3d rate_dps = Eigen::Vector3d::Zero();    ///< 0x52: raw/32768 × 2000 °/s
  Eigen::Vector3d angle_deg = Eigen::Vector3d::Zero();   ///< 0x53: roll, pitch, yaw, [−180, 180)
  Eigen::Vector3d mag_counts = Eigen::Vector3d::Zero();  ///< 0x54: raw counts
  double temperature_c = 0;                              ///< 0x51, 0x52, 0x54: D3 / 100
  std::uint16_t version = 0;                             ///< 0x53: D3
  std::array<std::uint16_t, 4> registers{};              ///< 0x5F: four registers
};

struct WitDecoderStats {
  std::uint64_t packets_ok = 0, bad_checksum = 0, garbage_bytes = 0;
  std::uint64_t acc = 0, rate = 0, angle = 0, mag = 0, register_reads = 0, other_types = 0;
};

class Wt901cDecoder {
 public:
  using Handler = std::function<void(const WitPacket&)>;
  explicit Wt901cDecoder(Handler h) : handler_(std::move(h)) {}
  void Feed(std::string_view bytes);
  const WitDecoderStats& stats() const { return stats_; }

 private:
  void Scan();
  void Emit(const unsigned char* p);
  static constexpr std::size_t kPacket = 11;
  Handler handler_;
  WitDecoderStats stats_;
  std::array<unsigned char, 2 * kPacket> buf_{};
  std::size_t len_ = 0;
};

}  // namespace hil::estimator::drivers

#pragma once
/// @file
/// Tolerant decoder of Nooploop LinkTrack NLink_LinkTrack_Tag_Frame0 (seeds_001_003.md §C.2.1):
/// 128 bytes, `55 01`, little-endian, int24 fields, sum-8 over bytes 0–126 in byte 127. Bytes may
/// arrive in any pieces; bytes that cannot start a frame are garbage; a bad sum is counted and the
/// search resumes one byte after the header. Never throws; fixed buffer, no allocation.
/// Independent of the emulator's encoder (firmware_emu/src/uwb), tied to it by vectors/uwb.

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>

#include <Eigen/Core>

namespace hil::estimator::drivers {

struct LinkTrackTagFrame {
  std::uint8_t id = 0, role = 0;
  Eigen::Vector3d p_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_mps = Eigen::Vector3d::Zero();
  std::array<double, 8> dis_m{};
  Eigen::Vector3d gyro_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d acc_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d angle_deg = Eigen::Vector3d::Zero();
  Eigen::Vector4d quat_wxyz = Eigen::Vector4d::Zero();
  std::uint32_t local_time_ms = 0, system_time_ms = 0;
  Eigen::Vector3d eop_m = Eigen::Vector3d::Zero();
  double voltage_v = 0;
};

struct LinkTrackDecoderStats {
  std::uint64_t frames_ok = 0, bad_checksum = 0, garbage_bytes = 0;
};

class LinkTrackDecoder {
 public:
  using Handler = std::function<void(const LinkTrackTagFrame&)>;
  explicit LinkTrackDecoder(Handler h) : handler_(std::move(h)) {}
  void Feed(std::string_view bytes);
  const LinkTrackDecoderStats& stats() const { return stats_; }

 private:
  void Scan();
  void Emit(const unsigned char* p);
  static constexpr std::size_t kFrame = 128;
  Handler handler_;
  LinkTrackDecoderStats stats_;
  std::array<unsigned char, 2 * kFrame> buf_{};
  std::size_t len_ = 0;
};

}  // namespace hil::estimator::drivers

#pragma once
/// @file
/// Tolerant decoder of HIL-UWB-TDOA0, the project's raw TDOA frame (vectors/uwb/README.md): 24
/// bytes, `55 D7`, tag id, n = 3, uint32 system_time ms, three int32 t_i1 (ps), 3 reserved, sum-8
/// of bytes 0–22. Bytes may arrive in any pieces; a byte that cannot start a frame is garbage
/// (NLink frames sharing the stream count there); a bad sum or n ≠ 3 is counted and the search
/// resumes one byte after the header. Never throws; fixed buffer, no allocation. Independent of
/// the emulator's encoder (firmware_emu/src/uwb), tied to it by vectors/uwb/uwb_tag_session.*.

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>

#include <Eigen/Core>

namespace hil::estimator::drivers {

struct UwbTdoaSample {
  std::uint8_t id = 0;
  std::uint32_t system_time_ms = 0;
  std::array<std::int32_t, 3> t_i1_ps{};
  /// r_i1 = c·t_i1 with the frame's c = 3×10⁸ m/s (m), i = 2, 3, 4.
  Eigen::Vector3d r_i1_m = Eigen::Vector3d::Zero();
};

struct UwbTdoaDecoderStats {
  std::uint64_t frames_ok = 0, bad_checksum = 0, bad_count = 0, garbage_bytes = 0;
};

class UwbTdoaDecoder {
 public:
  using Handler = std::function<void(const UwbTdoaSample&)>;
  explicit UwbTdoaDecoder(Handler h) : handler_(std::move(h)) {}
  void Feed(std::string_view bytes);
  const UwbTdoaDecoderStats& stats() const { return stats_; }

 private:
  void Scan();
  static constexpr std::size_t kFrame = 24;
  Handler handler_;
  UwbTdoaDecoderStats stats_;
  std::array<unsigned char, 4 * kFrame> buf_{};
  std::size_t len_ = 0;
};

}  // namespace hil::estimator::drivers

#pragma once
/// @file
/// Tolerant host-side decoder of a Slamtec RPLIDAR A1/A2 response stream (seeds_001_003.md §C.4):
/// 7-byte descriptors `A5 5A len|mode type`, then what the descriptor announces: device info (20
/// bytes), health (3), sample rate (4), accessory-board flag (4), standard scan nodes (5 bytes,
/// check bit C = 1 and S = !(!S) verified) or legacy express capsules (84 bytes, sync nibbles 0xA
/// / 0x5 and the XOR checksum verified; each capsule's 32 samples come out when the next capsule
/// gives the end angle). Bytes outside a response (the banner after RESET) are counted as garbage;
/// a node or capsule that fails its checks is counted and the search resumes one byte on. A
/// descriptor may follow any response (a new request). Never throws; fixed buffers, no
/// allocation. Independent of the emulator (firmware_emu/src/lidar), tied to it by
/// vectors/rplidar.

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>

namespace hil::estimator::drivers {

/// One measurement: θ clockwise from the LiDAR's forward axis in degrees [0, 360); 0 m = none.
struct LidarPoint {
  double angle_deg = 0;
  double distance_m = 0;
  std::uint8_t quality = 0;
  bool start = false;  ///< first point of a new turn (nodes: the S flag; capsules: the angle wraps)
  bool express = false;
};

struct LidarInfo {
  std::uint8_t model = 0, firmware_major = 0, firmware_minor = 0, hardware = 0;
  std::array<std::uint8_t, 16> serial{};
};

struct LidarSingleResponse {
  std::uint8_t type = 0;  ///< 0x04 info, 0x06 health, 0x15 sample rate, 0xFF accessory flag
  LidarInfo info;
  std::uint8_t health_status = 0;
  std::uint16_t health_error = 0, standard_us = 0, express_us = 0;
  std::uint32_t acc_board_flag = 0;
};

struct RplidarDecoderStats {
  std::uint64_t descriptors = 0, responses = 0, nodes = 0, capsules = 0, bad_nodes = 0,
                bad_capsules = 0, garbage_bytes = 0, unknown_types = 0;
};

class RplidarDecoder {
 public:
  using PointHandler = std::function<void(const LidarPoint&)>;
  using ResponseHandler = std::function<void(const LidarSingleResponse&)>;
  RplidarDecoder(PointHandler on_point, ResponseHandler on_response = {})
      : on_point_(std::move(on_point)), on_response_(std::move(on_response)) {}
  void Feed(std::string_view bytes);
  const RplidarDecoderStats& stats() const { return stats_; }

 private:
  enum class State { kIdle, kSingle, kNodes, kCapsules };
  /// Consumes from the buffer's start; false when more bytes are needed.
  bool Step();
  bool TryDescriptor();
  void Drop(std::size_t n);
  void Single();
  bool Node();
  bool Capsule();
  void EmitCapsule(std::uint16_t next_start_q6);

  PointHandler on_point_;
  ResponseHandler on_response_;
  State state_ = State::kIdle;
  std::uint8_t type_ = 0;
  std::size_t single_len_ = 0;
  std::array<unsigned char, 256> buf_{};
  std::size_t len_ = 0;
  std::array<unsigned char, 84> prev_capsule_{};
  bool have_prev_ = false;
  double prev_angle_deg_ = 0;
  RplidarDecoderStats stats_;
};

}  // namespace hil::estimator::drivers

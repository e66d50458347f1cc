#pragma once
/// @file
/// Nooploop LinkTrack NLink_LinkTrack_Tag_Frame0 (seeds_001_003.md §C.2.1): a fixed 128-byte frame,
/// header 0x55, function mark 0x01, little-endian, int24 = 3-byte signed; the last byte is the low
/// 8 bits of the sum of bytes 0–126. Scalings: position and distance mm, velocity 1e-4 m/s, angle
/// 0.01°, eop 0.01 m, voltage mV. Reserved bytes are zero.

#include <array>
#include <cstdint>
#include <string>

#include <Eigen/Core>

namespace hil::linktrack {

inline constexpr std::size_t kTagFrame0Size = 128;
inline constexpr std::uint8_t kTagFrame0Header = 0x55, kTagFrame0Mark = 0x01;

/// Field offsets in the frame.
namespace tag_frame0 {
inline constexpr std::size_t kId = 2, kRole = 3, kPos = 4, kVel = 13, kDis = 22, kGyro = 46,
                             kAcc = 58, kAngle = 82, kQuat = 88, kLocalTime = 108,
                             kSystemTime = 112, kEop = 117, kVoltage = 120, kCheck = 127;
}

/// Roles (nlink).
enum class Role : std::uint8_t { kNode = 0, kAnchor = 1, kTag = 2, kConsole = 3 };

struct TagFrame0 {
  std::uint8_t id = 0;
  Role role = Role::kTag;
  Eigen::Vector3d p_m = Eigen::Vector3d::Zero();  ///< position in the anchors' frame (ENU-like)
  Eigen::Vector3d v_mps = Eigen::Vector3d::Zero();
  std::array<double, 8> dis_m{};                         ///< distances to anchors 0–7
  Eigen::Vector3f gyro_radps = Eigen::Vector3f::Zero();  ///< float32 as the module sends it
  Eigen::Vector3f acc_mps2 = Eigen::Vector3f::Zero();
  Eigen::Vector3d angle_deg = Eigen::Vector3d::Zero();      ///< roll, pitch, yaw
  Eigen::Vector4f quat_wxyz = Eigen::Vector4f(1, 0, 0, 0);  ///< order q0 (w), q1, q2, q3
  std::uint32_t local_time_ms = 0, system_time_ms = 0;
  Eigen::Vector3d eop_m = Eigen::Vector3d::Zero();  ///< position precision estimate
  double voltage_v = 0;
};

/// The 128-byte frame. Values beyond a field's range saturate (int24 ±8388607 mm = ±8.4 km).
std::string EncodeTagFrame0(const TagFrame0& f);

/// Low 8 bits of the sum of `n` bytes at `p`.
std::uint8_t NlinkSum8(const char* p, std::size_t n);

}  // namespace hil::linktrack

#pragma once
/// @file
/// Nooploop LinkTrack NLink_LinkTrack_Setting_Frame0 (seeds_001_003.md §C.2.1): 128 bytes, header
/// 0x54, function mark 0x00; byte 2 mix, 3 role, 9 id, 36 group, ten anchor slots of 9 bytes (x,
/// y, z int24 mm) from byte 37, sum-8 of bytes 0–126 in byte 127. A host asks for the settings
/// with `54 00 01` + 124 zero bytes + 0x55 (ArduPilot's request); the tag answers with a
/// Setting_Frame0 whose anchor slots hold the anchors it knows, −8388000 in every coordinate of an
/// unused slot.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace hil::linktrack {

inline constexpr std::size_t kSettingFrame0Size = 128;
inline constexpr std::uint8_t kSettingFrame0Header = 0x54, kSettingFrame0Mark = 0x00;
inline constexpr std::size_t kSettingAnchorSlots = 10;
inline constexpr std::size_t kSettingAnchorOffset = 37;
/// The int24 value of a coordinate that is not available.
inline constexpr std::int32_t kSettingNotAvailable = -8388000;

namespace setting_frame0 {
inline constexpr std::size_t kMix = 2, kRole = 3, kId = 9, kGroup = 36, kCheck = 127;
inline constexpr std::uint8_t kMixReadRequest = 0x01;  ///< byte 2 of the host's read request
}  // namespace setting_frame0

struct SettingFrame0 {
  std::uint8_t mix = 0;
  std::uint8_t role = 2;  ///< tag
  std::uint8_t id = 0;
  std::uint8_t group = 0;
  std::vector<Eigen::Vector3d> p_anchor_m;  ///< at most ten; the rest are "not available"
};

/// The 128-byte frame (anchors beyond the tenth are ignored).
std::string EncodeSettingFrame0(const SettingFrame0& f);

/// The host's read request (ArduPilot's form).
std::string EncodeSettingReadRequest();

/// True when `frame` (128 bytes) is a Setting_Frame0 with a correct sum and mix = read request.
bool IsSettingReadRequest(std::string_view frame);

}  // namespace hil::linktrack

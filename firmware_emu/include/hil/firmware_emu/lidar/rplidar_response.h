#pragma once
/// @file
/// Slamtec RPLIDAR A1/A2 responses (device → host; seeds_001_003.md §C.4, Slamtec rplidar_sdk
/// `sl_lidar_protocol.h` read, not copied): the 7-byte response descriptor, the data payloads of
/// GET_INFO, GET_HEALTH, GET_SAMPLERATE and GET_ACC_BOARD_FLAG, the 5-byte standard scan node and
/// the 84-byte express (legacy) capsule. Little-endian.

#include <array>
#include <cstdint>
#include <string>

namespace hil::lidar {

/// Data types of the descriptors.
enum class DataType : std::uint8_t {
  kDeviceInfo = 0x04,
  kHealth = 0x06,
  kSampleRate = 0x15,
  kScanNode = 0x81,
  kExpressCapsule = 0x82,
  kAccBoardFlag = 0xFF,
};

inline constexpr std::size_t kDescriptorSize = 7, kNodeSize = 5, kCapsuleSize = 84, kCabins = 16,
                             kSamplesPerCapsule = 32;

/// `A5 5A` + u32 (length in the low 30 bits, mode in the top 2: 0 single, 1 multiple) + type.
std::string EncodeDescriptor(std::uint32_t length, bool multiple, DataType type);

struct DeviceInfo {
  std::uint8_t model = 0x18;
  std::uint8_t firmware_minor = 29, firmware_major = 1;
  std::uint8_t hardware = 7;
  std::array<std::uint8_t, 16> serial{};
};
std::string EncodeDeviceInfo(const DeviceInfo& d);
/// status 0 good, 1 warning, 2 error.
std::string EncodeHealth(std::uint8_t status, std::uint16_t error_code);
std::string EncodeSampleRate(std::uint16_t standard_us, std::uint16_t express_us);
std::string EncodeU32(std::uint32_t v);

/// One standard node: quality (6 bits), start-of-scan flag S, angle (q6, degrees × 64, clockwise),
/// distance (q2, mm × 4; 0 = no return).
struct ScanNode {
  std::uint8_t quality = 0;
  bool start = false;
  std::uint16_t angle_q6 = 0;
  std::uint16_t distance_q2 = 0;
};
/// byte0 = quality << 2 | !S << 1 | S; bytes 1–2 = angle_q6 << 1 | 1 (check bit); bytes 3–4.
std::string EncodeNode(const ScanNode& n);

/// One legacy express capsule: 32 distances (mm, 0 = none) sampled from `start_angle_q6` on at
/// equal angle steps up to the next capsule's start angle; all angle offsets 0 (the samples lie
/// exactly on the interpolated angles); `new_scan` on the first capsule after the request.
struct ExpressCapsule {
  std::uint16_t start_angle_q6 = 0;
  bool new_scan = false;
  std::array<std::uint16_t, kSamplesPerCapsule> distance_mm{};
};
std::string EncodeCapsule(const ExpressCapsule& c);

}  // namespace hil::lidar

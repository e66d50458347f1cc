#pragma once
/// @file
/// ISO 11783-7 guidance messages on the guidance controller's side (vectors/isobus/README.md):
/// encodes Agricultural Guidance System Command (PGN 44288, 0xAD00) and decodes Agricultural
/// Guidance Machine Info (PGN 44032, 0xAC00) and Wheel-based Speed and Distance (PGN 65096,
/// 0xFE48). Written independently of the steering ECU's codec in firmware_emu; the golden frames
/// in vectors/isobus/guidance_golden.txt tie the two. Curvature in km⁻¹, positive = right (ISOBUS);
/// the controller's own curvature (1/m, positive = left) converts with `IsobusCurvatureFromLeft`.
/// Never throws on input.

#include <array>
#include <cstdint>

namespace hil::estimator::guidance {

inline constexpr std::uint32_t kPgnMachineInfo = 0xAC00;         ///< 44032
inline constexpr std::uint32_t kPgnSystemCommand = 0xAD00;       ///< 44288
inline constexpr std::uint32_t kPgnWheelSpeedDistance = 0xFE48;  ///< 65096

/// A classic CAN frame with a 29-bit identifier.
struct IsobusFrame {
  std::uint32_t id = 0;
  std::uint8_t len = 0;
  std::array<std::uint8_t, 8> data{};
};

/// κ_ISOBUS [km⁻¹, + right] from κ [1/m, + left].
constexpr double IsobusCurvatureFromLeft(double curvature_left_per_m) {
  return -1000.0 * curvature_left_per_m;
}

/// Curvature command status values.
inline constexpr std::uint8_t kNotIntendedToSteer = 0;
inline constexpr std::uint8_t kIntendedToSteer = 1;
inline constexpr std::uint8_t kCommandError = 2;

struct SystemCommandAddress {
  std::uint8_t priority = 3;
  std::uint8_t source = 0x80;       ///< the guidance controller
  std::uint8_t destination = 0x1C;  ///< the steering ECU (0xFF = global)
};

/// Encodes a command: raw = round half away from zero((κ + 8032) / 0.25), clamped to 0 … 64255;
/// byte 2 = 0xFC | status; bytes 3–7 = 0xFF.
IsobusFrame EncodeSystemCommand(const SystemCommandAddress& address, double curvature_per_km,
                                std::uint8_t status);

struct MachineInfo {
  std::uint8_t source = 0;
  double estimated_curvature_per_km = 0;
  bool curvature_valid = false;  ///< raw ≤ 64255
  std::uint8_t mechanical_lockout = 3, readiness = 3, input_position_status = 3;
  std::uint8_t request_reset = 3, limit_status = 7, exit_reason = 63, remote_engage_switch = 3;
};

struct WheelSpeedDistance {
  std::uint8_t source = 0;
  double speed_mps = 0;  ///< magnitude; see `direction`
  bool speed_valid = false;
  double distance_m = 0;
  bool distance_valid = false;
  std::uint8_t max_time_of_tractor_power_min = 0xFF;
  std::uint8_t direction = 3, key_switch = 3, implement_start_stop = 3;
  std::uint8_t operator_direction_reversed = 3;
};

enum class IsobusDecodeResult : std::uint8_t { kOk, kOtherPgn, kWrongLength };

/// PGN of a 29-bit identifier (PDU1: the destination byte cleared).
std::uint32_t PgnOfId(std::uint32_t id29);
IsobusDecodeResult DecodeMachineInfo(const IsobusFrame& frame, MachineInfo& out);
IsobusDecodeResult DecodeWheelSpeedDistance(const IsobusFrame& frame, WheelSpeedDistance& out);

}  // namespace hil::estimator::guidance

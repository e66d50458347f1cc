#pragma once
/// @file
/// ISO 11783-7 guidance and speed messages on the steering ECU's side (vectors/isobus/README.md,
/// vectors/can/hil_imu.dbc): the ECU decodes Agricultural Guidance System Command (PGN 44288,
/// 0xAD00) and encodes Agricultural Guidance Machine Info (PGN 44032, 0xAC00) and Wheel-based Speed
/// and Distance (PGN 65096, 0xFE48). Curvature is in ISOBUS units and sign: km⁻¹, positive =
/// turning to the driver's right in forward travel.

#include <cstdint>

#include "hil/firmware_emu/device.h"

namespace hil::actuator {

inline constexpr std::uint32_t kPgnGuidanceMachineInfo = 44032;      ///< 0xAC00, PDU1
inline constexpr std::uint32_t kPgnGuidanceSystemCommand = 44288;    ///< 0xAD00, PDU1
inline constexpr std::uint32_t kPgnWheelBasedSpeedDistance = 65096;  ///< 0xFE48, PDU2

inline constexpr double kCurvatureResolution_per_km = 0.25;
inline constexpr double kCurvatureOffset_per_km = -8032.0;
inline constexpr std::uint16_t kCurvatureRawMax =
    64255;  ///< highest valid raw value (8031.75 km⁻¹)

/// raw = round half away from zero ((κ − offset) / 0.25), clamped to 0 … 64255.
std::uint16_t EncodeCurvatureRaw(double curvature_per_km);
double CurvatureFromRaw(std::uint16_t raw);

/// The parts of a 29-bit J1939 identifier (PDU1: `destination` from PS; PDU2: 0xFF).
struct J1939IdFields {
  std::uint8_t priority = 0;
  std::uint32_t pgn = 0;
  std::uint8_t source = 0;
  std::uint8_t destination = 0xFF;
};
J1939IdFields SplitJ1939Id(std::uint32_t id29);
/// priority << 26 | PGN << 8 | SA, with DA in the PS byte for PDU1 PGNs (PF < 240).
std::uint32_t MakeJ1939Id(std::uint8_t priority, std::uint32_t pgn, std::uint8_t source,
                          std::uint8_t destination);

/// Curvature command status (byte 2 bits 0–1).
enum class CurvatureCommandStatus : std::uint8_t {
  kNotIntendedToSteer = 0,
  kIntendedToSteer = 1,
  kError = 2,
  kNotAvailable = 3,
};

/// A decoded Guidance System Command.
struct GuidanceSystemCommand {
  std::uint16_t curvature_raw = 32128;
  double curvature_per_km = 0;  ///< only meaningful when `curvature_raw ≤ kCurvatureRawMax`
  CurvatureCommandStatus status = CurvatureCommandStatus::kNotAvailable;
};

/// Why a received frame is not a usable Guidance System Command.
enum class CommandFrameError : std::uint8_t {
  kNone = 0,
  kWrongLength,          ///< DLC ≠ 8
  kCurvatureOutOfRange,  ///< raw curvature > 64255 (error / not available indicators)
};

/// Decodes the 8 data bytes of a Guidance System Command; never throws.
CommandFrameError DecodeGuidanceSystemCommand(const CanFrame& frame, GuidanceSystemCommand& out);

/// The fields of Guidance Machine Info the ECU sends.
struct GuidanceMachineInfo {
  double estimated_curvature_per_km = 0;
  std::uint8_t mechanical_system_lockout = 0;  ///< 0 not active, 1 active, 2 error, 3 n/a
  std::uint8_t steering_system_readiness = 1;  ///< 0 off, 1 on/ready, 2 error, 3 n/a
  std::uint8_t steering_input_position_status = 3;
  std::uint8_t request_reset_command_status = 0;  ///< 1: guidance must drop "intended to steer"
  std::uint8_t guidance_limit_status = 0;  ///< 0 not, 1 operator, 2 high, 3 low, 6 fault, 7 n/a
  std::uint8_t exit_reason_code = 0;       ///< 6 bits (0 all clear, 5 timeout, 6 out of range …)
  std::uint8_t remote_engage_switch_status = 3;
};
/// Reserved bits (byte 3 bits 0–4, bytes 5–7) are sent as 1.
CanFrame EncodeGuidanceMachineInfo(Time t, std::uint8_t priority, std::uint8_t source,
                                   std::uint8_t destination, const GuidanceMachineInfo& info);

/// Wheel-based Speed and Distance.
struct WheelBasedSpeedDistance {
  double speed_mps = 0;   ///< 0.001 m/s per bit, 0 … 64.255 m/s
  double distance_m = 0;  ///< 0.001 m per bit, wraps beyond 4 211 081.215 m
  std::uint8_t max_time_of_tractor_power_min = 0xFF;  ///< 0xFF = not available
  std::uint8_t direction = 1;                         ///< 0 reverse, 1 forward, 2 error, 3 n/a
  std::uint8_t key_switch = 1;                        ///< 0 off, 1 not off
  std::uint8_t implement_start_stop = 3;
  std::uint8_t operator_direction_reversed = 3;
};
CanFrame EncodeWheelBasedSpeedDistance(Time t, std::uint8_t priority, std::uint8_t source,
                                       const WheelBasedSpeedDistance& msg);

}  // namespace hil::actuator

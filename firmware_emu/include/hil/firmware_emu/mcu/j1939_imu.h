#pragma once
/// @file
/// The MCU's CAN messages (vectors/can/README.md, vectors/can/hil_imu.dbc): J1939 Angular Rate
/// Information (PGN 61482), Acceleration Sensor (61485), Slope Sensor Information 2 (61481) and
/// the project's HIL_TIME_PULSE (proprietary B PGN 65360). Values are in the IMU frame I (FLU).

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "hil/firmware_emu/device.h"

namespace hil::mcu {

inline constexpr std::uint32_t kPgnSsi2 = 61481;
inline constexpr std::uint32_t kPgnAri = 61482;
inline constexpr std::uint32_t kPgnAccs = 61485;
inline constexpr std::uint32_t kPgnHilTimePulse = 65360;

/// Addressing of the J1939 messages.
struct J1939Address {
  std::uint8_t priority = 3;
  std::uint8_t source_address = 0xE2;
};

/// 29-bit identifier: priority << 26 | PGN << 8 | SA (PDU2 PGNs, no destination).
std::uint32_t J1939Id(const J1939Address& a, std::uint32_t pgn);

/// Figure of merit per axis (0 functional, 1 degraded, 2 error, 3 not available).
using FiguresOfMerit = std::array<std::uint8_t, 3>;

/// ARI from the inertial rate of I (rad/s): pitch rate −ω_y, roll rate ω_x, yaw rate ω_z.
CanFrame EncodeAri(Time t, const J1939Address& a, const Eigen::Vector3d& w_I_radps,
                   const FiguresOfMerit& fom, double latency_s);
/// ACCS from the specific force in I (m/s²): lateral f_y, longitudinal f_x, vertical f_z.
CanFrame EncodeAccs(Time t, const J1939Address& a, const Eigen::Vector3d& f_I_mps2,
                    const FiguresOfMerit& fom, double latency_s);
/// SSI2 pitch = atan2(f_x, √(f_y² + f_z²)), roll = atan2(f_y, f_z) from the specific force in I.
CanFrame EncodeSsi2(Time t, const J1939Address& a, const Eigen::Vector3d& f_I_mps2,
                    std::uint8_t pitch_fom, std::uint8_t roll_fom, double latency_s);
/// The pitch and roll (degrees) SSI2 reports for a specific force.
Eigen::Vector2d PitchRollDegFromSpecificForce(const Eigen::Vector3d& f_I_mps2);
/// HIL_TIME_PULSE: latched tick, GPS time of week (whole s; nullopt-like `valid` = false sends
/// 0xFFFFF) and the GPS week modulo 4096.
CanFrame EncodeHilTimePulse(Time t, const J1939Address& a, std::uint32_t tick, bool valid,
                            std::uint32_t tow_s, int gps_week);

}  // namespace hil::mcu

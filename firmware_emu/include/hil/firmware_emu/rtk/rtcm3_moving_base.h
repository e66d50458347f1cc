#pragma once
/// @file
/// RTCM 3 message 4072.0, the u-blox moving base's "reference station PVT": the message a ZED-F9P
/// moving base sends beside its MSM so that its rover can compute the baseline to a base that
/// moves. The ZED-F9P integration manual (UBX-18010802) names it (a moving-base rover "requires
/// both base station observation (MSM4 or MSM7 messages) and position message (RTCM 4072.0)")
/// and the ZED-F9T's lists 4072 as "Additional reference station information"; u-blox publishes
/// no layout. 4072 lies in the RTCM 3 proprietary range (4001–4095, one number per company).
/// Body only; rtcm3_frame.h frames it.
///
/// The layout is ours (180 bits, 23 bytes with padding): DF002 message number u12 (4072) ·
/// sub-type u12 (0) · DF003 reference station ID u12 (the ID of its MSM) · GPS epoch time u30
/// (ms of the week, as MSM's DF004) · antenna ECEF-X, -Y, -Z s38 each (0.0001 m, as DF025–
/// DF027). Only our rover reads it; a third-party decoder sees a valid frame of an unknown type.

#include <cstdint>
#include <string>

#include <Eigen/Core>

namespace hil::rtcm3 {

inline constexpr int kMovingBaseMessage = 4072;
inline constexpr int kMovingBaseSubtype = 0;
inline constexpr std::size_t kMovingBasePvtBytes = 23;  ///< the 4072.0 body (180 bits, padded)

/// What a 4072.0 carries: the moving base's antenna at its epoch.
struct MovingBasePvt {
  int station_id = 0;          ///< DF003, 0–4095: the same ID as in its MSM
  std::uint32_t epoch_ms = 0;  ///< GPS time of week of the epoch (ms)
  Eigen::Vector3d antenna_E_m = Eigen::Vector3d::Zero();  ///< ECEF
};

/// The 4072.0 body. @throws std::out_of_range for a field that does not fit.
std::string Encode4072Pvt(const MovingBasePvt& p);
/// The sub-type of a 4072 body (the 12 bits after DF002); −1 for another message or a short body.
int Subtype4072(const std::string& body);
/// Decodes a 4072.0 body. @throws std::invalid_argument for another message or length.
MovingBasePvt Decode4072Pvt(const std::string& body);

}  // namespace hil::rtcm3

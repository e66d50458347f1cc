#pragma once
/// @file
/// UBX output messages of a u-blox F9 (protocol 27+) built from one F9Epoch: NAV-PVT, NAV-HPPOSLLH,
/// NAV-SAT, NAV-RELPOSNED (version 1), RXM-RTCM and MON-VER of that generation. Every function
/// returns the payload; ubx::Frame() frames it. Layouts and units: the ZED-F9P interface
/// description (u-blox UBX-18010854, HPG 1.32), offsets in the comments of the implementation and
/// in vectors/gnss/README.md ("ZED-F9P messages").

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/gnss/nav_epoch.h"

namespace hil::gnss::ubx {

inline constexpr std::uint8_t kNavPvt = 0x07, kNavHpposllh = 0x14, kNavSat = 0x35,
                              kNavRelposned = 0x3C, kRxmRtcm = 0x32;

/// NAV-PVT carrSoln / RELPOSNED carrSoln.
enum class CarrSoln : std::uint8_t { kNone = 0, kFloat = 1, kFixed = 2 };

/// One navigation epoch of an F9 rover: the standalone receiver's epoch and its RTK state.
struct F9Epoch {
  NavEpoch nav;
  CarrSoln carr_soln = CarrSoln::kNone;
  bool diff_soln = false;          ///< differential corrections applied
  double correction_age_s = -1.0;  ///< age of the corrections in use; < 0: none
  bool relpos_valid = false;       ///< a base position (1005/1006) and its observations in use
  int ref_station_id = 0;          ///< the base's DF003
  Eigen::Vector3d rel_pos_NED_m = Eigen::Vector3d::Zero();  ///< rover antenna − base ARP
  Eigen::Vector3d rel_acc_NED_m = Eigen::Vector3d::Zero();  ///< 1-sigma per axis
  bool ref_pos_miss = false, ref_obs_miss = false;
  /// RELPOSNED's own carrSoln and diffSoln: the absolute solution's with a fixed base; with a
  /// moving base, those of the baseline (the absolute solution stays standalone).
  CarrSoln rel_carr_soln = CarrSoln::kNone;
  bool rel_diff_soln = false;
  bool is_moving = false;      ///< moving-base mode (RELPOSNED isMoving)
  bool heading_valid = false;  ///< relPosHeadingValid
  double acc_heading_deg = 0;  ///< accHeading (1-sigma); 0 when not computed
};

/// NAV-PVT (92 bytes).
std::vector<std::uint8_t> EncodeNavPvt(const F9Epoch& e);
/// NAV-HPPOSLLH (36 bytes, version 0).
std::vector<std::uint8_t> EncodeNavHpposllh(const F9Epoch& e);
/// NAV-SAT (version 1; 8 + 12 × satellites bytes). With differential corrections the used GPS
/// satellites are flagged diffCorr, rtcmCorrUsed, prCorrUsed and crCorrUsed.
std::vector<std::uint8_t> EncodeNavSat(const F9Epoch& e);
/// NAV-RELPOSNED (64 bytes, version 1): flags bit 0 gnssFixOK, 1 diffSoln, 2 relPosValid, 3–4
/// carrSoln, 5 isMoving, 6 refPosMiss, 7 refObsMiss, 8 relPosHeadingValid, 9 relPosNormalized
/// (never set here); relPosHeading and accHeading (1e-5 deg) at 24 and 52.
std::vector<std::uint8_t> EncodeNavRelposned(const F9Epoch& e);
/// RXM-RTCM (8 bytes, version 2) for one RTCM message received: its number (msgType), its
/// reference station, whether its CRC failed and whether it was used (msgUsed 2) or not (1).
std::vector<std::uint8_t> EncodeRxmRtcm(int msg_type, int ref_station, bool crc_failed, bool used);
/// The MON-VER strings of a ZED-F9P with firmware HPG 1.32 (vectors/gnss/README.md).
std::vector<std::uint8_t> EncodeF9MonVer();
/// NAV-PVT lastCorrectionAge (flags3 bits 1–4) for an age in seconds (< 0: not available).
std::uint8_t LastCorrectionAgeCode(double age_s);

}  // namespace hil::gnss::ubx

#pragma once
/// @file
/// The protocol-neutral navigation solution of one receiver epoch: what the receiver model
/// produces and what the UBX and NMEA back ends serialize. Back ends never see the truth.

#include <cstdint>

#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/unix_time.h"

namespace hil::gnss {

/// Fix type as the u-blox 5 reports it (NAV-SOL gpsFix).
enum class FixType : std::uint8_t {
  kNoFix = 0,
  kDeadReckoning = 1,
  k2D = 2,
  k3D = 3,
  kGpsDr = 4,
  kTimeOnly = 5
};

/// Quality beyond the fix type, for NMEA GGA's quality field and the RTK profile.
enum class FixQuality : std::uint8_t {
  kInvalid = 0,
  kGps = 1,
  kDgps = 2,
  kRtkFixed = 4,
  kRtkFloat = 5
};

/// One epoch's solution. Time of validity is the measurement epoch (`t_validity`); the bytes
/// carrying it leave the receiver later (output lag).
struct GnssFix {
  Time t_validity{};  ///< scenario time of the measurement epoch
  UnixTime utc{};     ///< the same instant as UTC
  FixType fix_type = FixType::kNoFix;
  FixQuality quality = FixQuality::kInvalid;
  double lat_deg = 0, lon_deg = 0;  ///< WGS-84, of the antenna
  double height_m = 0;              ///< ellipsoidal height of the antenna
  double geoid_separation_m = 0;    ///< geoid above ellipsoid (N); MSL altitude = height − N
  double vel_n_mps = 0, vel_e_mps = 0, vel_d_mps = 0;  ///< NED velocity as UBX reports it
  double h_acc_m = 0, v_acc_m = 0, s_acc_mps = 0;      ///< 1-sigma accuracy estimates
  double p_acc_m = 0;                                  ///< 3D position accuracy estimate
  double heading_acc_deg = 180.0;                      ///< course accuracy estimate
  double hdop = 99.99, vdop = 99.99, pdop = 99.99;
  double gdop = 99.99, tdop = 99.99, ndop = 99.99, edop = 99.99;
  int num_sv = 0;                   ///< satellites used
  double ground_speed_mps() const;  ///< horizontal speed
  double course_deg() const;        ///< course over ground, degrees clockwise from true north
  bool valid() const {
    return fix_type == FixType::k2D || fix_type == FixType::k3D || fix_type == FixType::kGpsDr;
  }
};

}  // namespace hil::gnss

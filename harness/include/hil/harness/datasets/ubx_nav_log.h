#pragma once
/// @file
/// GNSS fixes from a u-blox UBX log: NAV-PVT (01 07), or NAV-POSLLH (01 02) joined with
/// NAV-VELNED (01 12) of the same iTOW when the log has no NAV-PVT. Other messages (RXM-RAWX,
/// RXM-SFRBX, NMEA…) are skipped. Framing: B5 62, class, id, u16 length, payload, Fletcher-8
/// checksum over class..payload (u-blox interface description). Frames with a bad checksum and
/// a frame cut by the end of the log are counted, not fatal (a log is a byte stream); a NAV
/// message of the wrong length is an error naming the file, the byte offset and the message.
///
/// σ (u-blox gives accuracy estimates, not per-axis σ; chosen here, not u-blox's): north and east
/// σ = hAcc/√2 (hAcc taken as the horizontal RMS), down σ = vAcc, each velocity axis σ = sAcc.
/// Fixes kept: NAV-PVT with gnssFixOK and fixType 3 (3-D) or 4 (GNSS + dead reckoning);
/// NAV-POSLLH epochs all (the message has no fix flag).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hil::harness {

struct UbxNavFix {
  double sow = 0;                                 ///< iTOW, GPS seconds of week
  double lat_deg = 0, lon_deg = 0, height_m = 0;  ///< height above the ellipsoid
  double height_msl_m = 0;                        ///< hMSL (above the receiver's geoid model)
  Eigen::Vector3d std_ned_m = Eigen::Vector3d::Zero();
  bool has_velocity = false;
  Eigen::Vector3d v_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_std_ned_mps = Eigen::Vector3d::Zero();
  int carrier_solution = 0;  ///< NAV-PVT carrSoln: 0 none, 1 float, 2 fixed
};

struct UbxNavLog {
  std::vector<UbxNavFix> fixes;
  std::uint64_t frames = 0, bad_checksum = 0, cut_frames = 0, nav_pvt = 0, posllh = 0, velned = 0,
                not_fixed = 0;
  std::uint64_t duplicates = 0;  ///< fixes of a repeated iTOW (the first kept)
};

/// @throws ImportInputError for an unreadable file or a NAV message of the wrong length.
UbxNavLog ReadUbxNavLog(const std::string& path);

}  // namespace hil::harness

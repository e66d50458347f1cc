#pragma once
/// @file
/// RTKLIB solution files (.pos, as rnx2rtkp/rtkpost/rtknavi write them) in the geodetic form:
/// a '%' header whose last line names the columns, then one epoch a line:
///   GPST (yyyy/mm/dd hh:mm:ss.sss, or week and seconds of week), latitude(deg) longitude(deg)
///   height(m) Q ns sdn(m) sde(m) sdu(m) sdne(m) sdeu(m) sdun(m) age(s) ratio
///   [vn(m/s) ve(m/s) vu(m/s) sdvn sdve sdvu sdvne sdveu sdvun]
/// The columns are found by their header names, so files without velocities or with extra
/// columns are read too. Times must be GPST (RTKLIB's default); UTC/JST and ECEF or ENU
/// solutions are refused (a clear error, exit 2).

#include <string>
#include <vector>

#include <Eigen/Core>

namespace hil::harness {

struct RtklibPosEpoch {
  int week = 0;
  double sow = 0;
  double lat_deg = 0, lon_deg = 0, height_m = 0;
  int quality = 0;  ///< Q: 1 fix, 2 float, 3 SBAS, 4 DGPS, 5 single, 6 PPP
  int satellites = 0;
  Eigen::Vector3d std_ned_m = Eigen::Vector3d::Zero();  ///< sdn, sde, sdu (as D)
  bool has_velocity = false;
  Eigen::Vector3d v_ned_mps = Eigen::Vector3d::Zero();      ///< vn, ve, −vu
  Eigen::Vector3d v_std_ned_mps = Eigen::Vector3d::Zero();  ///< sdvn, sdve, sdvu
};

/// @throws ImportInputError naming file, line and field for a bad line, a time that repeats or
/// goes backwards, a latitude outside ±90°, a negative σ, or a header that is not GPST/geodetic.
std::vector<RtklibPosEpoch> ReadRtklibPos(const std::string& path);

}  // namespace hil::harness

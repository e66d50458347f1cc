#pragma once
/// @file
/// WGS-84 helpers the receiver emulator needs for its own output (ECEF position and velocity,
/// line-of-sight angles). Kept inside firmware_emu: the emulator must not depend on the harness
/// (which uses GeographicLib) nor on the estimator.

#include <Eigen/Core>

namespace hil::gnss {

inline constexpr double kWgs84A_m = 6378137.0;
inline constexpr double kWgs84E2 = 6.69437999014e-3;

/// ECEF position (m) of a geodetic WGS-84 point.
Eigen::Vector3d EcefFromGeodetic(double lat_deg, double lon_deg, double height_m);
/// Rotation taking ENU vectors at (lat, lon) into ECEF: v_E = R_EN * v_N.
Eigen::Matrix3d RotationEcefFromEnu(double lat_deg, double lon_deg);

}  // namespace hil::gnss

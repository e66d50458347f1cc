#pragma once
/// @file
/// The estimator's compact WGS-84 geodesy (independent of GeographicLib, which the harness uses to
/// check it): geodetic ↔ ECEF, and the local tangent frame N (ENU) at an origin in which the filter
/// mechanizes. Frames: N = ENU at the origin, E = ECEF.

#include <Eigen/Core>

namespace hil::estimator {

/// Geodetic WGS-84 coordinates.
struct Lla {
  double lat_deg = 0, lon_deg = 0, height_m = 0;
};

/// WGS-84 ellipsoid constants.
inline constexpr double kWgs84A_m = 6378137.0;
inline constexpr double kWgs84F = 1.0 / 298.257223563;
inline constexpr double kWgs84E2 = kWgs84F * (2.0 - kWgs84F);
/// Earth rotation rate (rad/s).
inline constexpr double kEarthRate_radps = 7.2921150e-5;

/// Geodetic → ECEF (m).
Eigen::Vector3d EcefFromLla(const Lla& g);
/// ECEF (m) → geodetic (iterative, converges to < 1e-9 m within 5 iterations on Earth).
Lla LlaFromEcef(const Eigen::Vector3d& p_E_m);
/// Normal gravity magnitude (m/s²) at a latitude and height (Somigliana with a free-air term).
double NormalGravity(double lat_deg, double height_m);

/// The ENU tangent frame at an origin.
class LocalTangentFrame {
 public:
  LocalTangentFrame() = default;
  explicit LocalTangentFrame(const Lla& origin);
  /// Geodetic → ENU position (m).
  Eigen::Vector3d ToLocal(const Lla& g) const;
  /// ENU position (m) → geodetic.
  Lla ToLla(const Eigen::Vector3d& p_N_m) const;
  /// Rotation from N (ENU at the origin) to ECEF axes.
  const Eigen::Matrix3d& R_EN() const { return R_EN_; }
  /// Earth rotation rate expressed in N (rad/s).
  Eigen::Vector3d w_IE_N() const;
  const Lla& origin() const { return origin_; }

 private:
  Lla origin_;
  Eigen::Vector3d p_E0_m_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_EN_ = Eigen::Matrix3d::Identity();
};

}  // namespace hil::estimator

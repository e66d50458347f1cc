#pragma once
/// @file
/// Geodesy for the truth: the local tangent frame N (**ENU**) at the scenario origin, and
/// conversions between it, geodetic WGS-84 coordinates and ECEF, through GeographicLib (an
/// independent implementation from the estimator's own compact geodesy).

#include <Eigen/Core>
#include <GeographicLib/LocalCartesian.hpp>

namespace hil::truth {

/// Geodetic WGS-84 coordinates.
struct Geodetic {
  double lat_deg = 0, lon_deg = 0, height_m = 0;
};

/// The ENU frame at an origin. N is fixed to the Earth: p_E = p_E(origin) + R_EN · p_N.
class LocalFrame {
 public:
  explicit LocalFrame(const Geodetic& origin);
  /// ENU position (m) → geodetic.
  Geodetic ToGeodetic(const Eigen::Vector3d& p_N_m) const;
  /// Geodetic → ENU position (m).
  Eigen::Vector3d FromGeodetic(const Geodetic& g) const;
  /// ENU position (m) → ECEF (m).
  Eigen::Vector3d ToEcef(const Eigen::Vector3d& p_N_m) const {
    return p_E_origin_m_ + R_EN_ * p_N_m;
  }
  /// ECEF (m) → ENU position (m).
  Eigen::Vector3d FromEcef(const Eigen::Vector3d& p_E_m) const {
    return R_EN_.transpose() * (p_E_m - p_E_origin_m_);
  }
  /// Rotation from ENU at the origin to ECEF axes.
  const Eigen::Matrix3d& R_EN() const { return R_EN_; }
  const Geodetic& origin() const { return origin_; }

 private:
  Geodetic origin_;
  GeographicLib::LocalCartesian lc_;
  Eigen::Matrix3d R_EN_;
  Eigen::Vector3d p_E_origin_m_;
};

}  // namespace hil::truth

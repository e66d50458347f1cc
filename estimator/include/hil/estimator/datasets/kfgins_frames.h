#pragma once
/// @file
/// KF-GINS's frames against navd's: KF-GINS works in NED with a body FRD (x forward, y right,
/// z down) and Euler angles roll, pitch, yaw (ZYX, yaw clockwise from north); navd's N is ENU and
/// its body FLU. Both conversions are their own inverses.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hil::estimator::datasets {

/// FRD ↔ FLU body vectors: (x, −y, −z).
inline Eigen::Vector3d FlipBody(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }
/// NED ↔ ENU navigation vectors: swap the first two, negate the third.
inline Eigen::Vector3d SwapNedEnu(const Eigen::Vector3d& v) { return {v.y(), v.x(), -v.z()}; }
/// NED ↔ ENU standard deviations (no sign).
inline Eigen::Vector3d SwapStd(const Eigen::Vector3d& s) { return {s.y(), s.x(), s.z()}; }

/// navd's q_NB (body FLU → ENU) from KF-GINS's roll, pitch, yaw (radians).
Eigen::Quaterniond QuatEnuFluFromEulerNed(const Eigen::Vector3d& rpy_rad);
/// KF-GINS's roll, pitch, yaw (radians; yaw in (−π, π]) from navd's q_NB.
Eigen::Vector3d EulerNedFromQuatEnuFlu(const Eigen::Quaterniond& q_NB);

}  // namespace hil::estimator::datasets

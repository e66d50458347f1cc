#include "hil/estimator/datasets/kfgins_frames.h"

#include <algorithm>
#include <cmath>

namespace hil::estimator::datasets {
namespace {
// ENU ← NED, and FRD ← FLU (each its own inverse)
Eigen::Matrix3d EnuFromNed() {
  Eigen::Matrix3d t;
  t << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  return t;
}
Eigen::Matrix3d FrdFromFlu() { return Eigen::Vector3d(1, -1, -1).asDiagonal(); }
}  // namespace

Eigen::Quaterniond QuatEnuFluFromEulerNed(const Eigen::Vector3d& rpy) {
  const Eigen::Matrix3d c_ned_frd = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                                     Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                                     Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                                        .toRotationMatrix();
  return Eigen::Quaterniond(EnuFromNed() * c_ned_frd * FrdFromFlu()).normalized();
}

Eigen::Vector3d EulerNedFromQuatEnuFlu(const Eigen::Quaterniond& q_NB) {
  const Eigen::Matrix3d c = EnuFromNed() * q_NB.toRotationMatrix() * FrdFromFlu();
  return {std::atan2(c(2, 1), c(2, 2)), std::asin(std::clamp(-c(2, 0), -1.0, 1.0)),
          std::atan2(c(1, 0), c(0, 0))};
}

}  // namespace hil::estimator::datasets

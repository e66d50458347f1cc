#include "hil/estimator/datasets/kfgins_frames.h"

#include <numbers>

#include <gtest/gtest.h>

namespace hil::estimator::datasets {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(KfginsFrames, YawIsClockwiseFromNorthAndBodyForwardIsShared) {
  // yaw 90°: the body's forward axis points east (ENU x)
  const Eigen::Quaterniond q = QuatEnuFluFromEulerNed(Eigen::Vector3d(0, 0, 90 * kDeg));
  EXPECT_NEAR((q * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX()).norm(), 0, 1e-12);
  // pitch up 10°: forward axis rises (ENU z > 0); roll right 10°: the left axis rises
  const Eigen::Quaterniond p = QuatEnuFluFromEulerNed(Eigen::Vector3d(0, 10 * kDeg, 0));
  EXPECT_NEAR((p * Eigen::Vector3d::UnitX()).z(), std::sin(10 * kDeg), 1e-12);
  const Eigen::Quaterniond r = QuatEnuFluFromEulerNed(Eigen::Vector3d(10 * kDeg, 0, 0));
  EXPECT_NEAR((r * Eigen::Vector3d::UnitY()).z(), std::sin(10 * kDeg), 1e-12);
}

TEST(KfginsFrames, EulerRoundTrips) {
  const Eigen::Vector3d rpy(3 * kDeg, -7 * kDeg, 170 * kDeg);
  const Eigen::Vector3d back = EulerNedFromQuatEnuFlu(QuatEnuFluFromEulerNed(rpy));
  EXPECT_NEAR((back - rpy).norm(), 0, 1e-12);
  EXPECT_EQ(FlipBody(Eigen::Vector3d(1, 2, 3)), Eigen::Vector3d(1, -2, -3));
  EXPECT_EQ(SwapNedEnu(Eigen::Vector3d(1, 2, 3)), Eigen::Vector3d(2, 1, -3));
}

}  // namespace
}  // namespace hil::estimator::datasets

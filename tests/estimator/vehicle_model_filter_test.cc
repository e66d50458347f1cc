// VehicleModelFilter: GNSS + a ground-vehicle model (CTRV with the non-holonomic constraint and
// the receiver's correlated error). On a straight line it averages a NEO-5M-like receiver's
// correlated error (σ 0.225 m, τ 4.5 s) below the fixes' own error with a σ that says so; on a
// circle it follows the turn with its lever arm.
#include "hil/estimator/vehicle_model_filter.h"

#include <cmath>
#include <random>

#include <Eigen/LU>
#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);

struct Result {
  double fused_rmse_m = 0, fix_rmse_m = 0, nees = 0;  // horizontal, after the first 60 s
};

// Body point on a circle of yaw rate w (0: a line) at speed v; antenna 0.84 m ahead, 0.5 m up.
Result RunLine(double v, double w, double duration_s, const VehicleModelParams& params) {
  VehicleModelFilter f(params);
  std::mt19937 rng(3);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double tau = 4.5, sigma = 0.225, dt = 1.0;
  const double a = std::exp(-dt / tau);
  Eigen::Vector2d e(sigma * n01(rng), sigma * n01(rng));
  double se_fused = 0, se_fix = 0, nees = 0;
  int n = 0;
  for (double t = 0; t < duration_s; t += dt) {
    const double psi = 0.3 + w * t;
    const Eigen::Vector2d p = w == 0 ? Eigen::Vector2d(v * t * std::cos(0.3), v * t * std::sin(0.3))
                                     : Eigen::Vector2d(v / w * (std::sin(psi) - std::sin(0.3)),
                                                       -v / w * (std::cos(psi) - std::cos(0.3)));
    const Eigen::Vector2d l(0.84 * std::cos(psi), 0.84 * std::sin(psi));
    const Eigen::Vector2d v_ant =
        v * Eigen::Vector2d(std::cos(psi), std::sin(psi)) + w * Eigen::Vector2d(-l.y(), l.x());
    e = a * e + sigma * std::sqrt(1 - a * a) * Eigen::Vector2d(n01(rng), n01(rng));
    const Eigen::Vector2d white(0.04 * n01(rng), 0.04 * n01(rng));
    const Eigen::Vector3d p_fix((p + l + e + white).x(), (p + l + e + white).y(), 1.5);
    const Eigen::Vector3d v_fix(v_ant.x() + 0.1 * n01(rng), v_ant.y() + 0.1 * n01(rng), 0);
    f.AddFix(kT0 + Nanoseconds{std::llround(t * 1e9)}, p_fix, Eigen::Vector3d(0.04, 0.04, 1.0),
             true, v_fix, Eigen::Vector3d(0.1, 0.1, 0.2), 1.0);
    if (t < 60) continue;
    const Eigen::Vector2d err = f.state().head<2>() - p;
    const Eigen::Matrix2d P = f.covariance().topLeftCorner<2, 2>();
    se_fused += err.squaredNorm();
    se_fix += (p_fix.head<2>() - l - p).squaredNorm();
    nees += err.dot(P.inverse() * err);
    ++n;
  }
  EXPECT_TRUE(f.ready());
  EXPECT_NEAR(f.height_m(), 1.0, 1e-9);  // the fix's height less the lever arm's 0.5 m
  return {std::sqrt(se_fused / n), std::sqrt(se_fix / n), nees / n};
}

VehicleModelParams RobotParams() {
  VehicleModelParams p;
  p.lever_arm_B_m = Eigen::Vector3d(0.84, 0.0, 0.5);
  p.gnss_error_tau_s = 4.5;
  p.gnss_error_std_m = 0.225;
  p.speed_rw_mps_rthz = 5e-4;  // the robot's governed speed
  return p;
}

TEST(VehicleModelFilterTest, StraightLineAveragesTheCorrelatedError) {
  const Result r = RunLine(0.44, 0.0, 900, RobotParams());
  EXPECT_LT(r.fused_rmse_m, 0.75 * r.fix_rmse_m) << r.fused_rmse_m << " vs " << r.fix_rmse_m;
  // an honest σ: mean horizontal NEES near its 2 degrees of freedom
  EXPECT_GT(r.nees, 0.5);
  EXPECT_LT(r.nees, 5.0);
}

TEST(VehicleModelFilterTest, CircleIsFollowedWithItsLeverArm) {
  // a 10 m circle at 1 m/s (0.1 rad/s): the yaw rate is learnt from the fixes
  const Result r = RunLine(1.0, 0.1, 900, RobotParams());
  EXPECT_LT(r.fused_rmse_m, r.fix_rmse_m) << r.fused_rmse_m << " vs " << r.fix_rmse_m;
  EXPECT_LT(r.nees, 5.0);
}

TEST(VehicleModelFilterTest, NeedsACourseToStartAndPredictsAlongTheHeading) {
  VehicleModelFilter f(RobotParams());
  const Eigen::Vector3d s(0.1, 0.1, 0.5), sv(0.05, 0.05, 0.1);
  EXPECT_FALSE(f.AddFix(kT0, Eigen::Vector3d(1, 2, 0), s, false, Eigen::Vector3d::Zero(), sv, 1));
  EXPECT_FALSE(f.ready());
  EXPECT_TRUE(f.AddFix(kT0, Eigen::Vector3d(0.84, 0, 0), s, true, Eigen::Vector3d(1, 0, 0), sv, 1));
  ASSERT_TRUE(f.ready());
  EXPECT_NEAR(f.state()(0), 0.0, 1e-9);  // body point = antenna − lever arm along the course
  VehicleModelFilter::Vector x;
  VehicleModelFilter::Matrix P;
  f.PredictTo(kT0 + std::chrono::seconds(2), x, P);
  EXPECT_NEAR(x(0), 2.0, 1e-9);
  EXPECT_NEAR(x(1), 0.0, 1e-9);
  EXPECT_GT(P(0, 0), f.covariance()(0, 0));
}

}  // namespace
}  // namespace hil::estimator

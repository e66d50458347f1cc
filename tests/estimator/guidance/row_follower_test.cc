// Paper 001's guidance as a whole in a small kinematic world: a differential-drive vehicle drives
// north along an aisle 1.5 m wide (ridge sides at E = ±0.75 m, the set line D_set = 0.5 m from the
// right ridge for units 0.25 m off the centre: E = 0) following a planned path on E = 0 from an
// estimate that is wrong by a constant 0.10 m (it believes the vehicle 0.10 m right of where it
// is). Without the correction the vehicle follows the estimate and stays 0.10 m off; with it the
// corrector brings it back and the re-anchoring keeps it there.
#include "hil/estimator/guidance/row_follower.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace hil::estimator::guidance {
namespace {

constexpr double kHalfAisle_m = 0.75, kFront_m = 0.2, kRear_m = -0.2, kSide_m = 0.25;
constexpr double kDt_s = 0.01;  // ranges at 100 Hz; the estimate and the command at 10 Hz

struct Pose {
  double e = 0, n = 0, yaw = std::numbers::pi / 2;
};

// The range of a unit at (xs, ys) in the body frame looking right (−1) or left (+1) to the ridge.
double Range(const Pose& p, double xs, double ys, int side) {
  const double c = std::cos(p.yaw), s = std::sin(p.yaw);
  const double se = p.e + c * xs - s * ys;
  const double de = -s * side;  // east component of the beam (body ±y)
  const double wall = side < 0 ? kHalfAisle_m : -kHalfAisle_m;
  return (wall - se) / de;
}

RangeSet Ranges(const Pose& p, double t_s) {
  RangeSet r;
  r.t = GpsTimeFromNs(std::llround(t_s * 1e9));
  r.right_front_m = Range(p, kFront_m, -kSide_m, -1);
  r.right_rear_m = Range(p, kRear_m, -kSide_m, -1);
  r.left_front_m = Range(p, kFront_m, kSide_m, 1);
  r.left_rear_m = Range(p, kRear_m, kSide_m, 1);
  r.right_front_ok = r.right_rear_ok = r.left_front_ok = r.left_rear_ok = true;
  return r;
}

struct Result {
  double final_offset_m = 0, max_abs_offset_last_10_m_m = 0;
  std::uint64_t anchors = 0, lateral_corrections = 0;
};

Result DriveAisle(bool correction) {
  PlannedPath path;
  path.Append({0, -2}, SegmentKind::kStraight, 0);
  path.Append({0, 40}, SegmentKind::kStraight, 0);
  RowFollowerConfig c;
  c.speed_mps = 0.4;
  c.pursuit.lookahead_m = 1.0;
  c.correction = correction;
  RowFollower f(c, path);
  Pose p;
  VelocityCommand cmd;
  Result out;
  for (int i = 0; p.n < 30 && i < 20000; ++i) {
    const double t = i * kDt_s;
    if (i % 10 == 0) {
      VehiclePose2d est;
      est.p_EN_m = {p.e - 0.10, p.n};  // the estimate: 0.10 m right of the truth
      est.yaw_rad = p.yaw;
      est.speed_mps = cmd.v_mps;
      f.OnEstimate(GpsTimeFromNs(std::llround(t * 1e9)), est);
    }
    f.OnRanges(Ranges(p, t));
    if (i % 10 == 0) cmd = f.Command();
    p.yaw += cmd.w_radps * kDt_s;
    p.e += cmd.v_mps * kDt_s * std::cos(p.yaw);
    p.n += cmd.v_mps * kDt_s * std::sin(p.yaw);
    if (p.n > 20)
      out.max_abs_offset_last_10_m_m = std::max(out.max_abs_offset_last_10_m_m, std::abs(p.e));
  }
  out.final_offset_m = p.e;
  out.anchors = f.state().anchors;
  out.lateral_corrections = f.corrector().state().lateral_corrections;
  return out;
}

TEST(RowFollower, WithoutCorrectionTheEstimatesErrorStays) {
  const Result r = DriveAisle(false);
  EXPECT_NEAR(r.final_offset_m, 0.10, 0.01);  // the vehicle is where the estimate's line is
  EXPECT_EQ(r.anchors, 0u);
}

TEST(RowFollower, TheCorrectionBringsItBackAndTheAnchorKeepsIt) {
  const Result r = DriveAisle(true);
  EXPECT_GE(r.lateral_corrections, 1u);
  EXPECT_GE(r.anchors, 1u);
  // within D_m over the last 10 m (a correction starts once past D_m: a sample or two beyond)
  EXPECT_LT(r.max_abs_offset_last_10_m_m, 0.032);
}

TEST(RowFollower, WheelSpeedsFromSpeedAndYawRate) {
  const DiffDrivePlatform p{0.5, 0.1, 20.0};
  const WheelSpeeds w = WheelSpeedsFromSpeedAndYawRate(p, 0.4, 0.4);
  EXPECT_DOUBLE_EQ(w.left_radps, (0.4 - 0.1) / 0.1);
  EXPECT_DOUBLE_EQ(w.right_radps, (0.4 + 0.1) / 0.1);
  const WheelSpeeds spin = WheelSpeedsFromSpeedAndYawRate(p, 0.0, 0.6);  // in place
  EXPECT_DOUBLE_EQ(spin.left_radps, -spin.right_radps);
  const WheelSpeeds fast = WheelSpeedsFromSpeedAndYawRate(p, 4.0, 0.0);  // 40 rad/s: halved
  EXPECT_DOUBLE_EQ(fast.left_radps, 20.0);
}

}  // namespace
}  // namespace hil::estimator::guidance

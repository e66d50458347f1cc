// The tracker guidanced runs: chosen by name, both limited to the push rod's curvature on a
// front-steered platform; and the fuzzy tracker's tracking heading towards a point ahead
// (heading_preview_m), with hand-computed values.
#include "hil/estimator/guidance/selected_tracker.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace hil::estimator::guidance {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

PlannedPath EastLine() {
  PlannedPath p;
  p.Append({0, 0}, SegmentKind::kStraight, 0);
  p.Append({40, 0}, SegmentKind::kStraight, 0);
  return p;
}

TEST(SelectedTrackerTest, ParsesTheTwoNames) {
  EXPECT_EQ(ParseTrackerKind("pure_pursuit"), TrackerKind::kPurePursuit);
  EXPECT_EQ(ParseTrackerKind("fuzzy"), TrackerKind::kFuzzy);
  EXPECT_FALSE(ParseTrackerKind("stanley"));
  EXPECT_FALSE(ParseTrackerKind(""));
}

TEST(SelectedTrackerTest, PurePursuitIsLimitedToThePushRod) {
  SelectedTrackerConfig c;
  c.pure_pursuit.lookahead_m = 0.5;
  c.pure_pursuit.min_lookahead_m = 0.5;
  VehiclePose2d pose;
  pose.p_EN_m = {5, 0.4};
  pose.speed_mps = 0.5;
  // goal (5.5, 0): bearing −38.66°, distance 0.6403 m, κ = 2 sin α / D = −1.9512 1/m
  EXPECT_NEAR(SelectedTracker(c).Update(EastLine(), pose).curvature_left_per_m, -1.951220, 1e-5);
  c.wheelbase_m = 0.84;  // paper 003's platform: |κ| ≤ tan 32° / 0.84 m = 0.743892 1/m
  EXPECT_NEAR(SelectedTracker(c).Update(EastLine(), pose).curvature_left_per_m, -0.743892, 1e-6);
}

TEST(SelectedTrackerTest, FuzzyTakesThePlatformsWheelbaseAndRange) {
  SelectedTrackerConfig c;
  c.kind = TrackerKind::kFuzzy;
  c.wheelbase_m = 0.84;
  c.max_steer_deg = 32;
  SelectedTracker t(c);
  EXPECT_EQ(t.kind(), TrackerKind::kFuzzy);
  VehiclePose2d pose;
  pose.p_EN_m = {5, 0.3};
  // as fuzzy_tracker_test: α = −10.108546°, κ = tan α / 0.84
  EXPECT_NEAR(t.Update(EastLine(), pose).curvature_left_per_m, -0.212239, 1e-6);
}

TEST(SelectedTrackerTest, FuzzyTrackingHeadingTowardsAPointAhead) {
  FuzzyTrackerConfig f;
  f.heading_preview_m = 2.0;
  FuzzyTracker t(f);
  VehiclePose2d pose;
  pose.p_EN_m = {5, 0.3};  // 0.3 m left of the eastward line, heading along it
  const TrackingCommand c = t.Update(EastLine(), pose);
  // the goal (7, 0) bears −8.530766° from the vehicle: θ = −8.530766°, Θ = −0.853077;
  // n = 0.631784, A = −0.631784 × 3 + 0.368216 × (−0.853077) = −2.209469, α = −11.783833°
  EXPECT_NEAR(t.last_steer_rad() / kDeg, -11.783833, 1e-5);
  EXPECT_NEAR(c.heading_error_rad, 0.0, 1e-12) << "the reported heading error is the path's";
  f.k_alpha_deg = 0.17 / kDeg;  // the printed k_α read as radians per level: α = −21.520849°
  FuzzyTracker k(f);
  k.Update(EastLine(), pose);
  EXPECT_NEAR(k.last_steer_rad() / kDeg, -21.520849, 1e-5);
}

TEST(SelectedTrackerTest, FuzzyPreviewTurnsBeforeTheCorner) {
  PlannedPath p;  // north 10 m, then east (a right-hand corner)
  p.Append({0, 0}, SegmentKind::kStraight, 0);
  p.Append({0, 10}, SegmentKind::kStraight, 0);
  p.Append({10, 10}, SegmentKind::kStraight, 1);
  VehiclePose2d pose;
  pose.p_EN_m = {0, 9};  // on the line, 1 m before the corner, heading north
  pose.yaw_rad = 90 * kDeg;
  FuzzyTrackerConfig f;
  EXPECT_NEAR(FuzzyTracker(f).Update(p, pose).curvature_left_per_m, 0.0, 1e-12);
  f.heading_preview_m = 2.0;  // goal (1, 10): θ = −45°, Θ = −4.5, n = 0: α = −24° (right)
  FuzzyTracker t(f);
  t.Update(p, pose);
  EXPECT_NEAR(t.last_steer_rad() / kDeg, -24.0, 1e-9);
}

}  // namespace
}  // namespace hil::estimator::guidance

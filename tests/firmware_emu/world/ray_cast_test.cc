// Ray casting against boxes and segments, with rays whose answers are worked out by hand.
#include "hil/firmware_emu/world/ray_cast.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace hil::world {
namespace {

Ray2 RayAt(double x, double y, double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  return {Eigen::Vector2d(x, y), Eigen::Vector2d(std::cos(a), std::sin(a))};
}

TEST(CastBox, AxisAlignedFaceAheadHitsAtTheFaceWithItsNormal) {
  // a 2 × 1 box centred at (5, 0): faces x = 4 and x = 6, y = ±0.5
  const OrientedBox box{{5, 0}, {1, 0.5}, 0};
  const auto hit = CastBox(RayAt(0, 0, 0), box, 10);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m, 4.0, 1e-12);
  EXPECT_NEAR(hit->normal.x(), -1.0, 1e-12);
  EXPECT_NEAR(hit->normal.y(), 0.0, 1e-12);
}

TEST(CastBox, ObliqueRayEntersThroughTheSideFace) {
  // from (4, −2) at 45°: meets the face y = −0.5 at x = 5.5 (within 4 … 6), range 1.5·√2
  const OrientedBox box{{5, 0}, {1, 0.5}, 0};
  const auto hit = CastBox(RayAt(4, -2, 45), box, 10);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m, 1.5 * std::numbers::sqrt2, 1e-12);
  EXPECT_NEAR(hit->normal.y(), -1.0, 1e-12);
}

TEST(CastBox, RotatedBoxIsHitOnItsRotatedFace) {
  // the same box turned 90°: faces y = ±1 about (0, 5), x = ±0.5; a ray up the y axis meets y = 4
  const OrientedBox box{{0, 5}, {1, 0.5}, std::numbers::pi / 2};
  const auto hit = CastBox(RayAt(0, 0, 90), box, 10);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m, 4.0, 1e-12);
  EXPECT_NEAR(hit->normal.y(), -1.0, 1e-12);
  EXPECT_NEAR(hit->normal.x(), 0.0, 1e-12);
}

TEST(CastBox, MissesBehindBeyondRangeAndBeside) {
  const OrientedBox box{{5, 0}, {1, 0.5}, 0};
  EXPECT_FALSE(CastBox(RayAt(0, 0, 180), box, 10));  // behind
  EXPECT_FALSE(CastBox(RayAt(0, 0, 0), box, 3.9));   // face at 4 m beyond 3.9 m
  EXPECT_FALSE(CastBox(RayAt(0, 1, 0), box, 10));    // passes above y = 0.5
  EXPECT_FALSE(CastBox(RayAt(0, 0, 10), box, 10));   // at x = 4, y = 4·tan 10° = 0.705 > 0.5
}

TEST(CastBox, OriginInsideHitsAtZero) {
  const OrientedBox box{{5, 0}, {1, 0.5}, 0};
  const auto hit = CastBox(RayAt(5, 0, 30), box, 10);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->range_m, 0.0);
}

TEST(CastSegment, HitsAt45DegreesWithTheNormalFacingTheOrigin) {
  // wall x = 3 from y = −10 to 10; a ray at 45° meets it at (3, 3), range 3√2
  const auto hit = CastSegment(RayAt(0, 0, 45), {3, -10}, {3, 10}, 10);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m, 3 * std::numbers::sqrt2, 1e-12);
  EXPECT_NEAR(hit->normal.x(), -1.0, 1e-12);
  EXPECT_FALSE(CastSegment(RayAt(0, 0, 80), {3, -10}, {3, 10}, 20));   // meets x = 3 at y = 17
  EXPECT_FALSE(CastSegment(RayAt(0, 0, 90), {3, -10}, {3, 10}, 20));   // parallel
  EXPECT_FALSE(CastSegment(RayAt(0, 0, 180), {3, -10}, {3, 10}, 20));  // behind
}

TEST(MayHitCircle, RejectsOnlyWhatCannotBeHit) {
  EXPECT_TRUE(MayHitCircle(RayAt(0, 0, 0), {5, 0.9}, 1, 10));
  EXPECT_FALSE(MayHitCircle(RayAt(0, 0, 0), {5, 1.1}, 1, 10));
  EXPECT_FALSE(MayHitCircle(RayAt(0, 0, 0), {-2, 0}, 1, 10));
  EXPECT_FALSE(MayHitCircle(RayAt(0, 0, 0), {12, 0}, 1, 10));
}

}  // namespace
}  // namespace hil::world

// The greenhouse map: where ridges, walls and posts are, what rays from an aisle hit, and the
// layouts that make no sense.
#include "hil/firmware_emu/world/greenhouse_world.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

namespace hil::world {
namespace {

// Rows run east (0°) from (0, 0): ridge i's centre line is y = 1.8·i, sides at y = 1.8·i ± 0.3;
// aisle 0's centre line is y = 0.9, its clear width 1.2 m.
GreenhouseConfig EastRows() {
  GreenhouseConfig c;
  c.row_direction_deg = 0;
  c.ridge_count = 3;
  c.ridge_width_m = 0.6;
  c.ridge_spacing_m = 1.8;
  c.ridge_length_m = 20;
  c.headland_m = 3;
  c.side_margin_m = 1.5;
  c.post_spacing_m = 4;
  c.post_size_m = 0.1;
  return c;
}

Ray2 RayAt(double x, double y, double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  return {Eigen::Vector2d(x, y), Eigen::Vector2d(std::cos(a), std::sin(a))};
}

TEST(GreenhouseWorld, SideRaysFromTheAisleCentreMeetBothRidgeSides) {
  const GreenhouseWorld w(EastRows());
  // from (10, 0.9) at 0.15 m height: right (−90°) meets ridge 0's side y = 0.3 at 0.6 m, left
  // ridge 1's side y = 1.5 at 0.6 m
  const auto right = w.Cast(RayAt(10, 0.9, -90), 0.15, 12);
  ASSERT_TRUE(right);
  EXPECT_EQ(right->kind, ObstacleKind::kRidge);
  EXPECT_EQ(right->index, 0);
  EXPECT_NEAR(right->range_m, 0.6, 1e-12);
  EXPECT_NEAR(right->normal.y(), 1.0, 1e-12);
  const auto left = w.Cast(RayAt(10, 0.9, 90), 0.15, 12);
  ASSERT_TRUE(left);
  EXPECT_EQ(left->index, 1);
  EXPECT_NEAR(left->range_m, 0.6, 1e-12);
  // 5° off the perpendicular: 0.6 / cos 5°
  const auto skew = w.Cast(RayAt(10, 0.9, -85), 0.15, 12);
  ASSERT_TRUE(skew);
  EXPECT_NEAR(skew->range_m, 0.6 / std::cos(5 * std::numbers::pi / 180), 1e-12);
}

TEST(GreenhouseWorld, RaysAboveTheRidgesReachTheWalls) {
  const GreenhouseWorld w(EastRows());
  // at 0.5 m (above the 0.3 m ridges) a ray to the right crosses all rows to the side wall at
  // y = −0.3 − 1.5 = −1.8, through the post line? posts stand at x = −3 + 4k: x = 10 is clear
  const auto hit = w.Cast(RayAt(10, 0.9, -90), 0.5, 12);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->kind, ObstacleKind::kWall);
  EXPECT_NEAR(hit->range_m, 0.9 + 1.8, 1e-12);
  // along the aisle: the end wall at x = 20 + 3 = 23
  const auto ahead = w.Cast(RayAt(10, 0.9, 0), 0.15, 20);
  ASSERT_TRUE(ahead);
  EXPECT_EQ(ahead->kind, ObstacleKind::kWall);
  EXPECT_NEAR(ahead->range_m, 13.0, 1e-12);
  EXPECT_FALSE(w.Cast(RayAt(10, 0.9, 0), 0.15, 12.5));  // beyond the range
}

TEST(GreenhouseWorld, PostsStandInsideTheSideWalls) {
  const GreenhouseWorld w(EastRows());
  // posts at x = −3 + 4k (k = 0 … 6, the last clamped to 22.95), y = −1.75 and 5.35
  ASSERT_EQ(w.posts().size(), 14u);
  EXPECT_NEAR(w.posts()[0].centre_m.x(), -2.95, 1e-12);
  EXPECT_NEAR(w.posts()[2].centre_m.x(), 1.0, 1e-12);
  EXPECT_NEAR(w.posts()[2].centre_m.y(), -1.75, 1e-12);
  // a ray down at x = 1, 0.5 m high, meets that post's face at y = −1.7: range 0.9 + 1.7
  const auto hit = w.Cast(RayAt(1, 0.9, -90), 0.5, 12);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->kind, ObstacleKind::kPost);
  EXPECT_NEAR(hit->range_m, 2.6, 1e-12);
}

TEST(GreenhouseWorld, RotatedLayoutGivesTheSameRanges) {
  GreenhouseConfig c = EastRows();
  c.row_direction_deg = 90;  // rows run north: aisle 0's centre line is x = −0.9
  c.first_ridge_start_N_m = {5, 5};
  const GreenhouseWorld w(c);
  const Eigen::Vector2d p = w.AislePoint(0, 10, 0);
  EXPECT_NEAR(p.x(), 5 - 0.9, 1e-12);
  EXPECT_NEAR(p.y(), 15, 1e-12);
  const auto right = w.Cast({p, Eigen::Vector2d(1, 0)}, 0.15, 12);  // east = right of north
  ASSERT_TRUE(right);
  EXPECT_NEAR(right->range_m, 0.6, 1e-12);
  const AislePosition a = w.Locate(p + Eigen::Vector2d(0.05, 0));
  EXPECT_EQ(a.aisle, 0);
  EXPECT_NEAR(a.lateral_m, -0.05, 1e-12);  // east is to the right
  EXPECT_NEAR(a.along_m, 10, 1e-12);
  EXPECT_TRUE(a.between_ridges);
}

TEST(GreenhouseWorld, LocateClampsToTheOuterAisles) {
  const GreenhouseWorld w(EastRows());
  EXPECT_EQ(w.Locate({5, 2.5}).aisle, 1);
  EXPECT_NEAR(w.Locate({5, 2.5}).lateral_m, 2.5 - 2.7, 1e-12);
  EXPECT_EQ(w.Locate({5, 9}).aisle, 1);
  EXPECT_EQ(w.Locate({5, -1}).aisle, 0);
  EXPECT_FALSE(w.Locate({-1, 0.9}).between_ridges);
}

TEST(CheckGreenhouse, NamesTheFieldOfALayoutThatMakesNoSense) {
  GreenhouseConfig c = EastRows();
  c.ridge_spacing_m = 0.5;  // below the 0.6 m width
  auto p = CheckGreenhouse(c);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->field, "ridge_spacing_m");
  EXPECT_THROW(GreenhouseWorld{c}, std::invalid_argument);
  c = EastRows();
  c.post_size_m = 2;
  ASSERT_TRUE(CheckGreenhouse(c));
  EXPECT_EQ(CheckGreenhouse(c)->field, "post_size_m");
  c = EastRows();
  c.ridge_count = 0;
  EXPECT_EQ(CheckGreenhouse(c)->field, "ridge_count");
  EXPECT_FALSE(CheckGreenhouse(EastRows()));
}

}  // namespace
}  // namespace hil::world

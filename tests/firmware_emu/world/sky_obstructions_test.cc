// The sky's obstructions as a GNSS antenna sees them: lines of sight through tree lines and
// buildings, and the reflections off their faces, with answers worked out by hand.
#include "hil/firmware_emu/world/sky_obstructions.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace hil::world {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A tree line along east at north 10…16 m (6 m wide), 15 m tall, from east −100 to 100 m.
SkyObstacle TreeLine() {
  SkyObstacle o;
  o.kind = SkyObstacleKind::kTreeLine;
  o.footprint = {{0, 13}, {100, 3}, 0};
  o.height_m = 15;
  o.loss_db_per_m = 1.0;
  o.max_loss_db = 25;
  o.reflection_amplitude = 0.2;
  return o;
}

TEST(SkyObstructions, LowSatelliteBehindTheTreesCrossesThemOverTheirSlantWidth) {
  const SkyObstructions w({TreeLine()});
  // antenna 2 m high at the origin; due north at 30°: enters at 10 m (height 7.8 m < 15), leaves
  // at 16 m (11.2 m): slant 6 / cos 30° = 6.93 m at 1 dB/m
  const LineOfSight los = w.Trace({0, 0, 2}, 0.0, 30 * kDeg);
  EXPECT_EQ(los.crossed, 1);
  EXPECT_FALSE(los.blocked);
  EXPECT_NEAR(los.loss_db, 6.0 / std::cos(30 * kDeg), 1e-9);
}

TEST(SkyObstructions, PathLeavesThroughTheTopWhenItRisesAboveTheTrees) {
  const SkyObstructions w({TreeLine()});
  // at 50°: height 2 + 10·tan 50° = 13.9 m at entry, reaches 15 m at 1.1/sin 50° slant later
  const double el = 50 * kDeg;
  const double s_enter = 10 / std::cos(el), s_top = 13 / std::sin(el);
  const LineOfSight los = w.Trace({0, 0, 2}, 0.0, el);
  EXPECT_NEAR(los.loss_db, s_top - s_enter, 1e-9);
  // and clears them at 60° (2 + 10·tan 60° = 19.3 m)
  EXPECT_EQ(w.Trace({0, 0, 2}, 0.0, 60 * kDeg).crossed, 0);
  // the other way (south) nothing is in the way
  EXPECT_EQ(w.Trace({0, 0, 2}, std::numbers::pi, 10 * kDeg).crossed, 0);
}

TEST(SkyObstructions, LossIsCappedAndABuildingIsOpaque) {
  SkyObstacle trees = TreeLine();
  trees.loss_db_per_m = 10;
  SkyObstacle house;
  house.kind = SkyObstacleKind::kBuilding;
  house.footprint = {{0, -20}, {5, 5}, 0};
  house.height_m = 8;
  house.opaque = true;
  const SkyObstructions w({trees, house});
  EXPECT_NEAR(w.Trace({0, 0, 2}, 0.0, 30 * kDeg).loss_db, 25.0, 1e-12);
  const LineOfSight south = w.Trace({0, 0, 2}, std::numbers::pi, 10 * kDeg);
  EXPECT_TRUE(south.blocked);
  // over its roof from 25° up: 2 + 15·tan 25° = 9.0 m at its near face, above its 8 m
  EXPECT_FALSE(w.Trace({0, 0, 2}, std::numbers::pi, 25 * kDeg).blocked);
}

TEST(SkyObstructions, ReflectionOffTheFaceHasTheImageAntennasExcessPath) {
  const SkyObstructions w({TreeLine()});
  // the face y = 10 faces south (normal −y), 10 m from the antenna; a satellite due south at
  // 20° shines on it: excess path 2·d·cos(el)
  const auto r = w.StrongestReflection({0, 0, 2}, std::numbers::pi, 20 * kDeg);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->excess_path_m, 2 * 10 * std::cos(20 * kDeg), 1e-9);
  EXPECT_NEAR(r->amplitude, 0.2, 1e-12);
  // 30° off the normal: 2·d·cos(el)·cos(30°)
  const auto r30 = w.StrongestReflection({0, 0, 2}, (180 + 30) * kDeg, 20 * kDeg);
  ASSERT_TRUE(r30);
  EXPECT_NEAR(r30->excess_path_m, 2 * 10 * std::cos(20 * kDeg) * std::cos(30 * kDeg), 1e-9);
}

TEST(SkyObstructions, NoReflectionFromBehindTheFaceOrAboveItsTop) {
  const SkyObstructions w({TreeLine()});
  // a satellite to the north lights the far side of the trees, not the face the antenna sees
  EXPECT_FALSE(w.StrongestReflection({0, 0, 2}, 0.0, 20 * kDeg));
  // a high satellite's reflection point is above the 15 m top: 2 + 10·tan 60° = 19.3 m
  EXPECT_FALSE(w.StrongestReflection({0, 0, 2}, std::numbers::pi, 60 * kDeg));
  // beyond the end of the line (east 150 m) the mirror point misses the face
  EXPECT_FALSE(w.StrongestReflection({150, 0, 2}, std::numbers::pi, 20 * kDeg));
}

TEST(SkyObstructions, BadFiguresAreNamed) {
  SkyObstacle o = TreeLine();
  o.reflection_amplitude = 1.5;
  ASSERT_TRUE(CheckSkyObstacle(o));
  EXPECT_EQ(CheckSkyObstacle(o)->field, "reflection_amplitude");
  o = TreeLine();
  o.height_m = 0;
  EXPECT_EQ(CheckSkyObstacle(o)->field, "height_m");
  EXPECT_THROW(SkyObstructions({o}), std::invalid_argument);
}

}  // namespace
}  // namespace hil::world

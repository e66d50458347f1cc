#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "hil/truth/path.h"
#include "hil/truth/terrain.h"

namespace hil::truth {
namespace {

TEST(TruthPathTest, CrossTrackIsSignedLeftPositiveAndAlongTrackIsArcLength) {
  const Path p({{{0, 0}, {}, 0}, {{0, 10}, {}, 0}, {{10, 10}, {}, 0}});
  EXPECT_DOUBLE_EQ(p.length_m(), 20);
  // west of a northbound segment is its left
  EXPECT_NEAR(CrossTrackError(p, {-0.3, 4, 0}), 0.3, 1e-12);
  EXPECT_NEAR(CrossTrackError(p, {0.3, 4, 0}), -0.3, 1e-12);
  // second segment eastbound: north is left
  const PathProjection q = p.Project({5, 10.2});
  EXPECT_EQ(q.segment, 1u);
  EXPECT_NEAR(q.cross_track_m, 0.2, 1e-12);
  EXPECT_NEAR(q.along_m, 15, 1e-12);
  // beyond the end the last segment extends
  EXPECT_NEAR(p.Project({30, 9}).cross_track_m, -1, 1e-12);
  EXPECT_EQ(p.PointAt(25), Eigen::Vector2d(15, 10));
  EXPECT_EQ(p.PointAt(5), Eigen::Vector2d(0, 5));
}

TEST(TruthPathTest, RejectsDegeneratePaths) {
  EXPECT_THROW(Path({{{0, 0}, {}, 0}}), std::invalid_argument);
  EXPECT_THROW(Path({{{0, 0}, {}, 0}, {{0, 0}, {}, 0}}), std::invalid_argument);
  BoustrophedonSpec b;
  b.row_spacing_m = 5;
  b.turn_radius_m = 3;
  EXPECT_THROW(MakeBoustrophedon(b), std::invalid_argument);
}

TEST(TruthPathTest, Seed003RectangleIsClockwiseFromMinus7Minus7) {
  const Path p = MakeRectangle({-7, -7}, 15, 15, 0, true, 1);
  ASSERT_EQ(p.vertices().size(), 5u);
  EXPECT_TRUE(p.vertices()[1].p_N_m.isApprox(Eigen::Vector2d(-7, 8)));
  EXPECT_TRUE(p.vertices()[2].p_N_m.isApprox(Eigen::Vector2d(8, 8)));
  EXPECT_TRUE(p.vertices()[3].p_N_m.isApprox(Eigen::Vector2d(8, -7)));
  EXPECT_TRUE(p.vertices()[4].p_N_m.isApprox(Eigen::Vector2d(-7, -7)));
  EXPECT_NEAR(p.length_m(), 60, 1e-12);
  // inside a clockwise loop is to the right
  EXPECT_LT(CrossTrackError(p, {0, 0, 0}), 0);
}

TEST(TruthPathTest, BoustrophedonRowsAreParallelSpacedAndJoinedByTangentTurns) {
  BoustrophedonSpec b;
  b.row_length_m = 50;
  b.row_spacing_m = 8;
  b.rows = 3;
  b.turn_radius_m = 3;
  const Path p = MakeBoustrophedon(b);
  // ends at the far end of the third row, 16 m to the right (east) of the first
  EXPECT_TRUE(p.vertices().back().p_N_m.isApprox(Eigen::Vector2d(16, 50)));
  // every vertex of a turn lies on its quarter arcs or the straight between them
  const double turn_length = 3.14159265358979 * 3 + (8 - 2 * 3);
  EXPECT_NEAR(p.length_m(), 3 * 50 + 2 * turn_length, 0.05);  // arcs as 5° chords
  // the path never turns by more than the chord angle at a vertex: a follower sees a smooth turn
  for (std::size_t i = 1; i + 1 < p.vertices().size(); ++i) {
    const double c = p.direction(i - 1).dot(p.direction(i));
    EXPECT_GT(c, std::cos(5.01 * 3.14159265358979 / 180)) << i;
  }
  // rows are straight north–south lines at e = 0, 8, 16
  EXPECT_NEAR(CrossTrackError(p, {0, 25, 0}), 0, 1e-12);
  EXPECT_NEAR(std::abs(CrossTrackError(p, {8, 25, 0})), 0, 1e-12);
}

// The nearest point by scanning every segment in order (Project's definition, without pruning).
PathProjection ScanAllSegments(const Path& path, const Eigen::Vector2d& p) {
  PathProjection best;
  double best_d2 = std::numeric_limits<double>::infinity();
  const std::size_t n = path.segments();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d r = p - path.vertices()[i].p_N_m;
    const Eigen::Vector2d& u = path.direction(i);
    double a = r.dot(u);
    if (i > 0) a = std::max(a, 0.0);
    if (i + 1 < n) a = std::min(a, path.s_at_vertex(i + 1) - path.s_at_vertex(i));
    const double d2 = (r - a * u).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.segment = i;
      best.along_m = path.s_at_vertex(i) + a;
      best.cross_track_m = (u.x() * r.y() - u.y() * r.x() >= 0 ? 1.0 : -1.0) * std::sqrt(d2);
    }
  }
  return best;
}

TEST(TruthPathTest, ProjectGivesTheFullScansNearestPointBitForBit) {
  // GIVEN a field pattern of 10 rows (arcs of 5° steps: hundreds of segments) and points on,
  // near and far from it, also exactly on vertices and beyond both ends
  BoustrophedonSpec b;
  b.row_length_m = 170;
  b.rows = 10;
  const Path path = MakeBoustrophedon(b);
  ASSERT_GT(path.segments(), 100u);
  std::vector<Eigen::Vector2d> points;
  for (double x = -30; x <= 110; x += 0.73) {
    for (double y = -40; y <= 220; y += 1.31) points.emplace_back(x, y);
  }
  for (const PathVertex& v : path.vertices()) points.push_back(v.p_N_m);
  points.emplace_back(1e4, -1e4);
  // THEN Project (which skips runs of segments that cannot be nearer) agrees with the scan
  for (const Eigen::Vector2d& p : points) {
    const PathProjection a = path.Project(p), e = ScanAllSegments(path, p);
    ASSERT_EQ(a.segment, e.segment) << p.transpose();
    ASSERT_EQ(a.along_m, e.along_m) << p.transpose();
    ASSERT_EQ(a.cross_track_m, e.cross_track_m) << p.transpose();
  }
}

TEST(TruthPathTest, CircleVerticesLieOnTheCircle) {
  const Path p = MakeCircle({1, 2}, 5, 180, true, 2, 90);
  for (const auto& v : p.vertices())
    EXPECT_NEAR((v.p_N_m - Eigen::Vector2d(1, 2)).norm(), 5, 1e-12);
  EXPECT_TRUE(p.vertices().front().p_N_m.isApprox(Eigen::Vector2d(1, -3)));
  // counter-clockwise from the south point: heading east first
  EXPECT_GT(p.direction(0).x(), 0.99);
}

TEST(TruthTerrainTest, PlaneRisesAlongItsUphillHeading) {
  TerrainConfig c;
  c.type = TerrainConfig::Type::kPlane;
  c.slope_deg = 5;
  c.uphill_heading_deg = 90;  // east
  c.height_m = 1;
  const Terrain t(c);
  EXPECT_NEAR(t.Height({10, 3}), 1 + 10 * std::tan(5 * 3.14159265358979 / 180), 1e-12);
  EXPECT_NEAR(t.Gradient({0, 0}).y(), 0, 1e-15);
}

TEST(TruthTerrainTest, RoughGroundGradientAndJetsAreExactDerivatives) {
  TerrainConfig c;
  c.type = TerrainConfig::Type::kRough;
  c.amplitude_m = 0.1;
  c.seed = 42;
  const Terrain t(c);
  ASSERT_EQ(t.waves().size(), 8u);
  const double h = 1e-5;
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(0.3, -2), Eigen::Vector2d(17, 5.5)}) {
    const Eigen::Vector2d g = t.Gradient(p);
    EXPECT_NEAR(
        g.x(),
        (t.Height(p + Eigen::Vector2d(h, 0)) - t.Height(p - Eigen::Vector2d(h, 0))) / (2 * h),
        1e-8);
    EXPECT_NEAR(
        g.y(),
        (t.Height(p + Eigen::Vector2d(0, h)) - t.Height(p - Eigen::Vector2d(0, h))) / (2 * h),
        1e-8);
    // along e(t) = p.x + 0.7 t + 0.1 t², n(t) = p.y − 0.4 t: dz/dt = ∇z · (0.7, −0.4)
    Jet2 z, ze, zn;
    t.Evaluate(Jet2(p.x(), 0.7, 0.2), Jet2(p.y(), -0.4, 0), z, ze, zn);
    EXPECT_NEAR(z.d, g.dot(Eigen::Vector2d(0.7, -0.4)), 1e-12);
    const auto z_at = [&](double s) {
      return t.Height({p.x() + 0.7 * s + 0.1 * s * s, p.y() - 0.4 * s});
    };
    EXPECT_NEAR(z.dd, (z_at(1e-4) - 2 * z_at(0) + z_at(-1e-4)) / 1e-8, 1e-5);
  }
  // the same seed gives the same ground
  EXPECT_EQ(Terrain(c).Height({3, 4}), t.Height({3, 4}));
  c.seed = 43;
  EXPECT_NE(Terrain(c).Height({3, 4}), t.Height({3, 4}));
}

}  // namespace
}  // namespace hil::truth

// Planned-path files (vectors/paths/README.md): every shape's geometry, the example files, and
// errors that name the file, the line and the field.
#include "hil/estimator/guidance/path_file.h"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

namespace hil::estimator::guidance {
namespace {

// Length of a quarter arc of radius r stored as chords of at most `step` (as the reader does).
double QuarterArcAsChords(double r, double step) {
  const int n = static_cast<int>(std::ceil(r * std::numbers::pi / 2 / step));
  return n * 2 * r * std::sin(std::numbers::pi / 4 / n);
}

std::string Vectors(const std::string& name) {
  const char* dir = std::getenv("HIL_SOURCE_DIR");
  return std::string(dir ? dir : ".") + "/vectors/paths/" + name;
}

TEST(PathFile, AbLineIsOneStraightEdge) {
  const PlannedPath p = ReadPathFile(Vectors("ab_line_east_300m.path"));
  ASSERT_EQ(p.vertex_count(), 2u);
  EXPECT_DOUBLE_EQ(p.length_m(), 300.0);
  const PathProjection f = p.Project({150.0, -1.0});
  EXPECT_DOUBLE_EQ(f.cross_track_m, -1.0);  // south of an eastward line = right = negative
  EXPECT_DOUBLE_EQ(f.s_m, 150.0);
  EXPECT_DOUBLE_EQ(f.path_yaw_rad, 0.0);
}

TEST(PathFile, BoustrophedonHasRowsAndHeadlandTurns) {
  const PlannedPath p = ReadPathFile(Vectors("boustrophedon_4rows.path"));
  EXPECT_NEAR(p.length_m(), 4 * 60 + 6 * QuarterArcAsChords(3.0, 0.1), 1e-9);
  EXPECT_NEAR(p.length_m(), 4 * 60 + 3 * 3 * std::numbers::pi, 2e-3);  // chords: −θ²/24
  EXPECT_EQ(p.segment_count(), 7);                                     // 4 rows, 3 turns
  const Eigen::Vector2d end = p.vertex(p.vertex_count() - 1);
  EXPECT_NEAR(end.x(), 18.0, 1e-9);  // first turn right: rows step east
  EXPECT_NEAR(end.y(), 0.0, 1e-9);   // the 4th row runs south back to the start line
  const PathProjection mid_turn = p.Project({3.0, 63.0});
  EXPECT_EQ(p.edge_kind(mid_turn.edge), SegmentKind::kTurn);
  EXPECT_NEAR(mid_turn.cross_track_m, 0.0, 1e-3);
  EXPECT_EQ(p.edge_kind(p.Project({6.0, 30.0}).edge), SegmentKind::kStraight);
}

TEST(PathFile, RectangleClosesOnItself) {
  const PlannedPath p = ReadPathFile(Vectors("rectangle_greenhouse.path"));
  const double r = 1.5;
  EXPECT_NEAR(p.length_m(), 2 * (20 + 8) - 8 * r + 4 * QuarterArcAsChords(r, 0.1), 1e-9);
  EXPECT_NEAR((p.vertex(0) - p.vertex(p.vertex_count() - 1)).norm(), 0.0, 1e-9);
  // The north side runs west: a point north of it is on the right of a counter-clockwise loop.
  EXPECT_NEAR(p.Project({10.0, 8.5}).cross_track_m, -0.5, 1e-9);
}

TEST(PathFile, PolylineAndCircle) {
  const PlannedPath poly = ReadPathFile(Vectors("polyline_dogleg.path"));
  EXPECT_EQ(poly.vertex_count(), 4u);
  EXPECT_NEAR(poly.length_m(), 30 + std::sqrt(500.0) + 30, 1e-12);
  const PlannedPath c = ReadPathFile(Vectors("circle_r20.path"));
  EXPECT_NEAR(c.length_m(), 2 * 2 * std::numbers::pi * 20, 0.01);
  EXPECT_NEAR(c.Project({0.0, 19.0}).cross_track_m, 1.0, 1e-3);  // inside a ccw circle = left
}

TEST(PathFile, Paper003RectangleAndLine) {
  // 15 m x 15 m from A(-7, -7), clockwise: north first, then east; four sharp corners
  const PlannedPath r = ReadPathFile(Vectors("seed003_rectangle_15m.path"));
  ASSERT_EQ(r.vertex_count(), 5u);
  EXPECT_DOUBLE_EQ(r.length_m(), 60.0);
  EXPECT_EQ(r.vertex(0), r.vertex(4));
  EXPECT_DOUBLE_EQ(r.vertex(1).y(), 8.0);
  EXPECT_DOUBLE_EQ(r.vertex(2).x(), 8.0);
  EXPECT_NEAR(r.Project({-7.5, 0.0}).cross_track_m, 0.5, 1e-12);  // west of a northward side: left
  // 15 m north at x = 0 through the field, 5 m beyond B
  const PlannedPath l = ReadPathFile(Vectors("seed003_line_north_15m.path"));
  EXPECT_DOUBLE_EQ(l.length_m(), 20.0);
  EXPECT_NEAR(l.Project({-1.795, -7.5}).cross_track_m, 1.795, 1e-12);  // state 1's start
}

void ExpectError(const std::string& text, int line, const std::string& field) {
  try {
    ParsePathText(text, "field.path");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const PathFileError& e) {
    EXPECT_EQ(e.file(), "field.path");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(
        std::string(e.what()).find("field.path:" + std::to_string(line) + ": field '" + field),
        std::string::npos)
        << e.what();
  }
}

TEST(PathFile, ErrorsNameFileLineAndField) {
  ExpectError("ab_line a_m=0,0 b_m=1,0\n", 1, "header");
  ExpectError("hil-path 2\nab_line a_m=0,0 b_m=1,0\n", 1, "version");
  ExpectError("hil-path 1\n\n# c\nab_line a_m=0,0 b_m=x,0\n", 4, "b_m");
  ExpectError("hil-path 1\nab_line a_m=0,0\n", 2, "b_m");
  ExpectError("hil-path 1\nab_line a_m=0,0 b_m=5,0 speed=3\n", 2, "speed");
  ExpectError("hil-path 1\nspiral r=1\n", 2, "spiral");
  ExpectError(
      "hil-path 1\nboustrophedon start_m=0,0 heading_deg=0 row_length_m=50 "
      "row_spacing_m=3 rows=4 turn_radius_m=2\n",
      2, "turn_radius_m");
  ExpectError(
      "hil-path 1\nboustrophedon start_m=0,0 heading_deg=0 row_length_m=50 "
      "row_spacing_m=6 rows=2.5 turn_radius_m=2\n",
      2, "rows");
  ExpectError("hil-path 1\npolyline\nvertex p_m=0,0\n", 2, "vertex");
  ExpectError("hil-path 1\npolyline\nvertex p_m=0,0\npoint p_m=1,1\n", 4, "point");
  ExpectError(
      "hil-path 1\nrectangle corner_m=0,0 length_m=10 width_m=4 heading_deg=0 "
      "corner_radius_m=3\n",
      2, "corner_radius_m");
  ExpectError("hil-path 1\nab_line a_m=0,0 b_m=1,0\nab_line a_m=0,0 b_m=1,0\n", 3, "ab_line");
  ExpectError("hil-path 1\nab_line a_m=0,0 a_m=1,0\n", 2, "a_m");
}

TEST(PathFile, UnreadableFileIsAnError) {
  try {
    ReadPathFile("/nonexistent/x.path");
    ADD_FAILURE();
  } catch (const PathFileError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.field(), "file");
  }
}

}  // namespace
}  // namespace hil::estimator::guidance

// The evaluator's path reader against the controller's (two independent readers of one file
// format): every example path in vectors/paths gives the same polyline and the same segments,
// arcs included; bad fields name the file, the line and the field.
#include "hil/harness/scenario/path_file_reader.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "hil/estimator/guidance/path_file.h"
#include "hil/harness/eval/path_tracking.h"

namespace hil::harness {
namespace {

std::string PathsDir() {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : "..") + "/vectors/paths/";
}

struct Segments {
  int straight = 0, turn = 0;
};

TEST(PathFileReaderTest, EveryExamplePathIsTheControllersPolyline) {
  for (const char* name : {"ab_line_east_300m.path", "polyline_dogleg.path", "circle_r20.path",
                           "rectangle_greenhouse.path", "boustrophedon_4rows.path"}) {
    SCOPED_TRACE(name);
    const PathGeometry g = ReadPathGeometry(PathsDir() + name);
    const auto c = estimator::guidance::ReadPathFile(PathsDir() + name);
    // the controller keeps zero-length edges where a segment starts: compare without them
    std::vector<Eigen::Vector2d> cv{c.vertex(0)};
    std::set<int> c_straight, c_turn;
    for (std::size_t i = 1; i < c.vertex_count(); ++i) {
      if ((c.vertex(i) - cv.back()).norm() < 1e-9) continue;
      cv.push_back(c.vertex(i));
      const bool turn = c.edge_kind(i - 1) == estimator::guidance::SegmentKind::kTurn;
      (turn ? c_turn : c_straight).insert(c.edge_segment(i - 1));
    }
    ASSERT_EQ(g.vertices.size(), cv.size());
    for (std::size_t i = 0; i < cv.size(); ++i)
      EXPECT_LT((g.vertices[i] - cv[i]).norm(), 1e-6) << "vertex " << i;
    ASSERT_EQ(g.edge_segment.size(), g.vertices.size() - 1);
    Segments s;
    for (const bool turn : g.segment_is_turn) (turn ? s.turn : s.straight) += 1;
    EXPECT_EQ(s.straight, static_cast<int>(c_straight.size()));
    EXPECT_EQ(s.turn, static_cast<int>(c_turn.size()));
    // segments in order, each a run of edges
    for (std::size_t e = 1; e < g.edge_segment.size(); ++e)
      EXPECT_LE(g.edge_segment[e] - g.edge_segment[e - 1], 1);
  }
}

TEST(PathFileReaderTest, TrackingFiguresPerRowAndTurn) {
  // a vehicle 0.1 m left of the whole boustrophedon: every segment scores 0.1 m
  const PathGeometry g = ReadPathGeometry(PathsDir() + "boustrophedon_4rows.path");
  std::vector<TrackSample> track;
  for (std::size_t i = 0; i + 1 < g.vertices.size(); ++i) {  // each edge's midpoint
    const Eigen::Vector2d d = (g.vertices[i + 1] - g.vertices[i]).normalized();
    TrackSample s;
    s.t = TimeFromNs(static_cast<std::int64_t>(i) * 100'000'000);
    s.p_N_m = 0.5 * (g.vertices[i] + g.vertices[i + 1]) + 0.1 * Eigen::Vector2d(-d.y(), d.x());
    s.yaw_rad = std::atan2(d.y(), d.x());
    s.speed_mps = 1;
    track.push_back(s);
  }
  const TrackingMetrics m = ScoreTracking(g, track, 0.2);
  ASSERT_EQ(m.segments.size(), g.segment_is_turn.size());
  EXPECT_EQ(m.segments.size(), 7U) << "4 rows, 3 headland turns";
  for (const SegmentTracking& s : m.segments) {
    EXPECT_EQ(s.kind, s.index % 2 == 1 ? "turn" : "straight");
    EXPECT_GT(s.stats.samples, 0U);
    EXPECT_NEAR(s.stats.mean_abs_m, 0.1, 0.002) << s.index;
    EXPECT_LT(s.start_s_m, s.end_s_m);
  }
}

class BadPathTest : public ::testing::Test {
 protected:
  void Expect(const std::string& text, int line, const std::string& field) {
    const std::string file =
        (std::filesystem::temp_directory_path() / "bad_eval_reader.path").string();
    std::ofstream(file) << text;
    try {
      ReadPathGeometry(file);
      FAIL() << "no error for " << text;
    } catch (const PathFileReadError& e) {
      const std::string want = file + ":" + std::to_string(line) + ": field '" + field + "'";
      EXPECT_EQ(std::string(e.what()).rfind(want, 0), 0U) << e.what();
    }
    std::filesystem::remove(file);
  }
};

TEST_F(BadPathTest, NamesFileLineAndField) {
  Expect("hil-path 1\ncircle center_m=0,0 radius_m=-2\n", 2, "radius_m");
  Expect("hil-path 1\ncircle center_m=0,0 radius_m=5 direction=up\n", 2, "direction");
  Expect("hil-path 1\ncircle center_m=0,0 radius_m=5 step_m=1e-9\n", 2, "step_m");
  Expect("hil-path 1\n# a comment\ncircle center_m=0;0 radius_m=5\n", 3, "center_m");
  Expect(
      "hil-path 1\nrectangle corner_m=0,0 length_m=10 width_m=4 heading_deg=0 "
      "corner_radius_m=3\n",
      2, "corner_radius_m");
  Expect(
      "hil-path 1\nboustrophedon start_m=0,0 heading_deg=90 row_length_m=20 row_spacing_m=2 "
      "rows=2.5 turn_radius_m=1\n",
      2, "rows");
  Expect(
      "hil-path 1\nboustrophedon start_m=0,0 heading_deg=90 row_length_m=20 row_spacing_m=2 "
      "rows=3 turn_radius_m=1.5\n",
      2, "turn_radius_m");
  Expect(
      "hil-path 1\nboustrophedon start_m=0,0 heading_deg=x row_length_m=20 row_spacing_m=2 "
      "rows=3 turn_radius_m=1\n",
      2, "heading_deg");
  Expect("hil-path 1\nab_line a_m=0,0 b_m=10,0 speed_mps=2\n", 2, "speed_mps");
  Expect("hil-path 1\nab_line a_m=0,0 b_m=10,0\nab_line a_m=0,0 b_m=10,0\n", 3, "ab_line");
  Expect("hil-path 1\nspiral center_m=0,0\n", 2, "spiral");
}

}  // namespace
}  // namespace hil::harness

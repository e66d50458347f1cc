// The evaluator's own path reader on boustrophedon files (vectors/paths/README.md): rows and
// headland turns as segments, the geometry from the format (lengths, end points, chord error),
// and a file with an error names the file, the line and the field.
#include "hil/harness/eval/path_file_reader.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "hil/harness/eval/path_tracking.h"

namespace hil::harness {
namespace {

std::string Vector(const std::string& rel) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/" + rel;
}

double Length(const PathFileShape& p, const PathSpan& s) {
  double l = 0;
  for (std::size_t e = s.first_edge; e < s.end_edge; ++e)
    l += (p.vertices[e + 1] - p.vertices[e]).norm();
  return l;
}

TEST(PathFileReaderTest, BoustrophedonRowsAndTurns) {
  const PathFileShape p = ReadPathFile(Vector("vectors/paths/boustrophedon_tractor_4rows.path"));
  ASSERT_EQ(p.spans.size(), 7u) << "4 rows, 3 turns";
  const double turn_len = std::numbers::pi * 3.5 + 0.5;  // two quarter arcs of 3.5 m + 0.5 m
  for (std::size_t k = 0; k < p.spans.size(); ++k) {
    EXPECT_EQ(p.spans[k].turn, k % 2 == 1) << k;
    const double expected = p.spans[k].turn ? turn_len : 60.0;
    EXPECT_NEAR(Length(p, p.spans[k]), expected, p.spans[k].turn ? 2e-3 : 1e-9) << k;
  }
  EXPECT_NEAR(p.vertices.front().x(), 0, 1e-12);
  EXPECT_NEAR(p.vertices.back().x(), 22.5, 1e-9) << "three spacings east (first turn right)";
  EXPECT_NEAR(p.vertices.back().y(), 0, 1e-9) << "the fourth row ends where the first began";
  // the first turn's apex: 3.5 m beyond the row end
  double max_n = 0;
  for (std::size_t e = p.spans[1].first_edge; e <= p.spans[1].end_edge; ++e)
    max_n = std::max(max_n, p.vertices[e].y());
  EXPECT_NEAR(max_n, 63.5, 1e-9);
}

TEST(PathFileReaderTest, SegmentsOfTheTrackingFiguresAreRowsAndTurns) {
  const PathFileShape p = ReadPathFile(Vector("vectors/paths/boustrophedon_4rows.path"));
  std::vector<TrackSample> track;
  for (int i = 0; i < 600; ++i)  // up the first row 2 cm right of it
    track.push_back({TimeFromNs(i * 100'000'000LL), {0.02, 0.1 * i}, std::numbers::pi / 2, 1.0});
  const TrackingMetrics m = ScoreTracking(p.vertices, track, 0.05, p.spans);
  ASSERT_EQ(m.segments.size(), 7u);
  EXPECT_EQ(m.segments[0].kind, "straight");
  EXPECT_EQ(m.segments[1].kind, "turn");
  EXPECT_NEAR(m.straight.mean_abs_m, 0.02, 1e-9);
  EXPECT_EQ(m.turns.samples, 0u);
}

TEST(PathFileReaderTest, ErrorsNameTheFileLineAndField) {
  const std::string f = ::testing::TempDir() + "/bad_boustrophedon.path";
  std::ofstream(f) << "hil-path 1\n# rows too close for the turn\n"
                      "boustrophedon start_m=0,0 heading_deg=0 row_length_m=60 row_spacing_m=4 "
                      "rows=2 turn_radius_m=3\n";
  try {
    ReadPathFile(f);
    FAIL() << "a turn radius above S/2 is an error";
  } catch (const PathFileReadError& e) {
    EXPECT_NE(std::string(e.what()).find(f + ":3: field 'turn_radius_m'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hil::harness

// Path tracking figures of a closed loop: the settled figures after an initial offset, and paper
// 003's from the start (mean and max of the whole run, the stable point at the first zero
// crossing, the steady-state mean after it), on a track with hand-counted deviations.
#include "hil/harness/eval/path_tracking.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

// 1 m/s along an eastward 20 m line, one sample a metre, at the given lateral offsets (then 0).
std::vector<TrackSample> Track(const std::vector<double>& y_m) {
  std::vector<TrackSample> t;
  for (int i = 0; i < 20; ++i) {
    TrackSample s;
    s.t = Time{} + std::chrono::seconds(i);
    s.p_N_m = {i, i < static_cast<int>(y_m.size()) ? y_m[static_cast<std::size_t>(i)] : 0.0};
    s.speed_mps = 1.0;
    t.push_back(s);
  }
  return t;
}

const std::vector<Eigen::Vector2d> kLine{{0, 0}, {20, 0}};

TEST(PathTrackingTest, FromTheStartAndTheStablePointAfterAnOffset) {
  const TrackingMetrics m = ScoreTracking(kLine, Track({1.0, 0.6, 0.2, -0.1}), 0.05);
  EXPECT_DOUBLE_EQ(m.initial_cross_track_m, 1.0);
  // settled into the 5 cm band at sample 4 (x = 4 m): the settled figures are zeros
  ASSERT_TRUE(m.settling_distance_m);
  EXPECT_DOUBLE_EQ(*m.settling_distance_m, 4.0);
  EXPECT_DOUBLE_EQ(m.all.max_abs_m, 0.0);
  // from the start: (1 + 0.6 + 0.2 + 0.1) / 20 samples, max 1 m
  EXPECT_EQ(m.from_start.samples, 20u);
  EXPECT_NEAR(m.from_start.mean_abs_m, 1.9 / 20, 1e-12);
  EXPECT_DOUBLE_EQ(m.from_start.max_abs_m, 1.0);
  // the deviation first changes sign at x = 3 m; after it 0.1 m once in 17 samples
  ASSERT_TRUE(m.stable_distance_m);
  EXPECT_DOUBLE_EQ(*m.stable_distance_m, 3.0);
  ASSERT_TRUE(m.steady_state_mean_abs_m);
  EXPECT_NEAR(*m.steady_state_mean_abs_m, 0.1 / 17, 1e-12);
}

TEST(PathTrackingTest, NoStablePointWithoutAnOffsetOrACrossing) {
  const TrackingMetrics on = ScoreTracking(kLine, Track({0.0, 0.03, -0.02}), 0.05);
  EXPECT_FALSE(on.stable_distance_m);  // started on the line
  EXPECT_NEAR(on.from_start.mean_abs_m, on.all.mean_abs_m, 1e-12);
  const TrackingMetrics never = ScoreTracking(kLine, Track(std::vector<double>(20, 0.5)), 0.05);
  EXPECT_FALSE(never.stable_distance_m);  // 0.5 m left all the way
  EXPECT_FALSE(never.settling_distance_m);
  EXPECT_DOUBLE_EQ(never.from_start.mean_abs_m, 0.5);
}

// The figures of a set as a sort of all its values gives them (the evaluation before issue 40).
XteStats Reference(const std::vector<double>& xte) {
  XteStats s;
  s.samples = xte.size();
  std::vector<double> absv;
  double sum = 0, sq = 0;
  for (const double x : xte) {
    absv.push_back(std::fabs(x));
    sum += absv.back();
    sq += x * x;
  }
  const auto n = static_cast<double>(xte.size());
  s.mean_abs_m = sum / n;
  s.rmse_m = std::sqrt(sq / n);
  std::sort(absv.begin(), absv.end());
  s.max_abs_m = absv.back();
  s.p95_abs_m = absv[static_cast<std::size_t>(std::ceil(0.95 * n)) - 1];
  return s;
}

void ExpectSame(const XteStats& got, const XteStats& want, const char* what) {
  EXPECT_EQ(got.samples, want.samples) << what;
  EXPECT_EQ(got.mean_abs_m, want.mean_abs_m) << what;  // the same additions in the same order
  EXPECT_EQ(got.rmse_m, want.rmse_m) << what;
  EXPECT_EQ(got.p95_abs_m, want.p95_abs_m) << what;
  EXPECT_EQ(got.max_abs_m, want.max_abs_m) << what;
  EXPECT_EQ(got.heading_rmse_deg, 0.0) << what;
}

TEST(PathTrackingTest, ALongTrackScoredInPassesGivesTheFiguresOfAllItsValues) {
  // GIVEN a U of three segments (a row east, a turn north, a row west) and 60 000 samples that
  // visit the three in turn (so a segment's samples are not together in time), random offsets
  std::vector<Eigen::Vector2d> v{{0, 0}, {100, 0}, {100, 50}, {0, 50}};
  PathGeometry g;
  g.vertices = v;
  g.edge_segment = {0, 1, 2};
  g.segment_is_turn = {false, true, false};
  std::mt19937_64 rng(3);
  std::normal_distribution<double> off(0.0, 0.02);
  std::uniform_real_distribution<double> along(10.0, 40.0);
  std::vector<TrackSample> track;
  std::vector<double> seg[3], all;
  for (int i = 0; i < 60000; ++i) {
    TrackSample s;
    s.t = Time{} + std::chrono::milliseconds(100 * i);
    s.speed_mps = 1.0;
    const double o = off(rng), a = along(rng);
    const int k = i % 3;
    double xte = 0;
    if (k == 0) s.p_N_m = {a, o}, s.yaw_rad = 0, xte = o;
    if (k == 1) s.p_N_m = {100 - o, a}, s.yaw_rad = std::atan2(1.0, 0.0), xte = -((100 - o) - 100);
    if (k == 2) s.p_N_m = {a, 50 + o}, s.yaw_rad = std::atan2(0.0, -1.0), xte = -((50 + o) - 50);
    track.push_back(s);
    seg[k].push_back(xte);
    all.push_back(xte);
  }
  // WHEN scored in passes (its values on disk, the percentiles selected from there)
  const TrackingMetrics m = ScoreTracking(g, track, 0.05);
  // THEN every figure is that of all the values at once: the run's in time order, each segment's,
  // and the straight segments' together in segment order (row 0's values, then row 2's)
  ExpectSame(m.all, Reference(all), "all");
  ExpectSame(m.from_start, Reference(all), "from start");
  ASSERT_EQ(m.segments.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) ExpectSame(m.segments[k].stats, Reference(seg[k]), "segment");
  std::vector<double> straight = seg[0];
  straight.insert(straight.end(), seg[2].begin(), seg[2].end());
  ExpectSame(m.straight, Reference(straight), "straight");
  ExpectSame(m.turns, Reference(seg[1]), "turns");
  // AND the plotted series is decimated: at most 3 points a bucket
  EXPECT_LE(m.xte_m.size(), 3 * kTrackingPlotBuckets);
  EXPECT_EQ(m.s_m.size(), m.xte_m.size());
}

}  // namespace
}  // namespace hil::harness

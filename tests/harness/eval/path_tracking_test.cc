// Path tracking figures of a closed loop: the settled figures after an initial offset, and paper
// 003's from the start (mean and max of the whole run, the stable point at the first zero
// crossing, the steady-state mean after it), on a track with hand-counted deviations.
#include "hil/harness/eval/path_tracking.h"

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

}  // namespace
}  // namespace hil::harness

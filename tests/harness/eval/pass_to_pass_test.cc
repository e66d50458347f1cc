// Pass-to-pass (ISO 12188-2 style) figures on synthetic tracks whose errors are known
// analytically: a second pass offset by a constant (a gap, an overlap, either side), a second pass
// wandering as a sine (mean |e| = 2A/π, p95 = A sin(0.95 π/2), max A), coarse samples of the
// first pass where nearest point and interpolation differ by sqrt(S² + (Δ/2)²) − S, the window,
// and straight segments that are not parallel (no pair).
#include "hil/harness/eval/pass_to_pass.h"

#include <cmath>
#include <functional>
#include <numbers>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

constexpr double kRowM = 100;

// Two 100 m rows: east along y = 0, then west along y = side·S, joined by a semicircle.
PathGeometry TwoRows(double spacing_m, double side = 1) {
  PathGeometry g;
  g.vertices.push_back({0, 0});
  g.vertices.push_back({kRowM, 0});
  g.edge_segment.push_back(0);
  g.segment_is_turn = {false, true, false};
  const double r = spacing_m / 2;
  for (int i = 1; i <= 30; ++i) {
    const double a = -std::numbers::pi / 2 + std::numbers::pi * i / 30;
    g.vertices.push_back({kRowM + r * std::cos(a), side * (r + r * std::sin(a))});
    g.edge_segment.push_back(1);
  }
  g.vertices.push_back({0, side * spacing_m});
  g.edge_segment.push_back(2);
  return g;
}

// Samples at x = x0, x0 + dx, … to x1 (either way) at 1 m/s, y(x), from time t0_s.
void Drive(std::vector<TrackSample>& track, double x0, double x1, double dx, double t0_s,
           const std::function<double(double)>& y) {
  const double dir = x1 >= x0 ? 1 : -1;
  const int n = static_cast<int>(std::floor(std::fabs(x1 - x0) / dx + 1e-9));
  for (int i = 0; i <= n; ++i) {
    TrackSample s;
    const double x = x0 + dir * dx * i;
    s.t = Time{} + DurationFromSeconds(t0_s + std::fabs(x - x0));
    s.p_N_m = {x, y(x)};
    s.yaw_rad = dir > 0 ? 0 : std::numbers::pi;
    s.speed_mps = 1;
    track.push_back(s);
  }
}

// Pass 1 on y = 0, then pass 2 back on y = side·(S + e), both sampled every 0.1 m at the same x.
std::vector<TrackSample> OffsetPasses(double spacing_m, double error_m, double side) {
  std::vector<TrackSample> t;
  Drive(t, 0, kRowM, 0.1, 0, [](double) { return 0.0; });
  Drive(t, kRowM, 0, 0.1, 120, [&](double) { return side * (spacing_m + error_m); });
  return t;
}

TEST(PassToPassTest, AConstantGapOrOverlapOnEitherSide) {
  for (const double side : {1.0, -1.0}) {
    for (const double e : {0.1, -0.2}) {
      const PassToPassMetrics m =
          ScorePassToPass(TwoRows(5, side), OffsetPasses(5, e, side), PassToPassConfig{});
      ASSERT_EQ(m.passes, 2u);
      ASSERT_EQ(m.pairs.size(), 1u);
      EXPECT_EQ(m.pairs[0].from_segment, 0);
      EXPECT_EQ(m.pairs[0].to_segment, 2);
      EXPECT_NEAR(m.pairs[0].spacing_m, 5, 1e-12);
      for (const PassErrorStats* s : {&m.nearest_point, &m.interpolated}) {
        EXPECT_NEAR(s->mean_m, e, 1e-9);  // + a gap, − an overlap
        EXPECT_NEAR(s->mean_abs_m, std::fabs(e), 1e-9);
        EXPECT_NEAR(s->p95_abs_m, std::fabs(e), 1e-9);
        EXPECT_NEAR(s->max_abs_m, std::fabs(e), 1e-9);
      }
      // 10 m margins: x in [10, 90] on both passes, 801 samples each
      EXPECT_EQ(m.interpolated.samples, 801u);
      EXPECT_NEAR(m.method_difference_max_m, 0, 1e-9);
      // absolute: pass 1 on its row, pass 2 e off it, away from pass 1 (+ left of travel west)
      EXPECT_EQ(m.absolute.samples, 1602u);
      EXPECT_NEAR(m.absolute.max_abs_m, std::fabs(e), 1e-9);
      EXPECT_NEAR(m.absolute.mean_m, -side * e / 2, 1e-9);
    }
  }
}

TEST(PassToPassTest, ASineWanderGivesItsAnalyticFigures) {
  constexpr double kA = 0.05, kWaveM = 20, kS = 7.5;
  std::vector<TrackSample> t;
  Drive(t, 0, kRowM, 0.1, 0, [](double) { return 0.0; });
  // x from 90 down to 10: four whole waves in the evaluated part, 4000 samples
  Drive(t, 90, 10, 0.02, 140,
        [](double x) { return kS + kA * std::sin(2 * std::numbers::pi * x / kWaveM); });
  const PassToPassMetrics m = ScorePassToPass(TwoRows(kS), t, PassToPassConfig{});
  ASSERT_EQ(m.pairs.size(), 1u);
  const PassErrorStats& ip = m.interpolated;
  EXPECT_EQ(ip.samples, 4001u);
  EXPECT_NEAR(ip.mean_m, 0, 1e-6);
  // 4000 samples over whole waves and one more at a zero: 2A/π · 4000/4001 (and a sum over 1000
  // phases a wave, within 1e-6 of the integral)
  EXPECT_NEAR(ip.mean_abs_m, 2 * kA / std::numbers::pi * 4000 / 4001, 1e-6);
  // the discrete quantile: within one phase step (2π/1000) of the value's slope there
  const double step = kA * std::cos(0.95 * std::numbers::pi / 2) * 2 * std::numbers::pi / 1000;
  EXPECT_NEAR(ip.p95_abs_m, kA * std::sin(0.95 * std::numbers::pi / 2), step);
  EXPECT_NEAR(ip.max_abs_m, kA, 1e-9);
  // nearest point: pass 1 sampled every 0.1 m, so at most sqrt(S'² + 0.05²) − S' more
  const double worst = std::sqrt((kS - kA) * (kS - kA) + 0.0025) - (kS - kA);
  EXPECT_GE(m.nearest_point.mean_m, ip.mean_m);  // never nearer than the polyline
  EXPECT_GT(m.method_difference_max_m, 0);
  EXPECT_LE(m.method_difference_max_m, worst + 1e-9);
}

TEST(PassToPassTest, CoarseSamplesSeparateNearestPointFromInterpolation) {
  // pass 1 every 2.5 m (5 m/s at 2 Hz), pass 2 exactly 3 m over, at the midpoints between them:
  // interpolation finds 0, the nearest sample sqrt(3² + 1.25²) − 3 = 0.25 m (Rounsaville et al.'s
  // hypothetical 25 cm)
  std::vector<TrackSample> t;
  Drive(t, 0, kRowM, 2.5, 0, [](double) { return 0.0; });
  Drive(t, 88.75, 11.25, 2.5, 130, [](double) { return 3.0; });
  const PassToPassMetrics m = ScorePassToPass(TwoRows(3), t, PassToPassConfig{});
  ASSERT_EQ(m.pairs.size(), 1u);
  const double expected = std::sqrt(9 + 1.25 * 1.25) - 3;
  EXPECT_NEAR(expected, 0.25, 1e-12);
  EXPECT_NEAR(m.interpolated.max_abs_m, 0, 1e-9);
  EXPECT_NEAR(m.nearest_point.mean_m, expected, 1e-9);
  EXPECT_NEAR(m.nearest_point.p95_abs_m, expected, 1e-9);
  EXPECT_NEAR(m.method_difference_max_m, expected, 1e-9);
  EXPECT_NEAR(m.method_difference_mean_m, expected, 1e-9);
}

TEST(PassToPassTest, TheWindowClipsThePasses) {
  PassToPassConfig c;
  c.window_s = 100;  // pass 2 starts at 120 s: outside
  const PassToPassMetrics m = ScorePassToPass(TwoRows(5), OffsetPasses(5, 0.1, 1), c);
  EXPECT_EQ(m.passes, 1u);
  EXPECT_TRUE(m.pairs.empty());
  EXPECT_EQ(m.interpolated.samples, 0u);
  EXPECT_NEAR(m.window_end_s, 90, 1e-9);  // the last sample inside the margins
  c.window_s = 150.05;                    // pass 2 up to x = 70 (t = 150 s): x in [70, 90]
  const PassToPassMetrics part = ScorePassToPass(TwoRows(5), OffsetPasses(5, 0.1, 1), c);
  ASSERT_EQ(part.pairs.size(), 1u);
  EXPECT_EQ(part.interpolated.samples, 201u);
}

TEST(PassToPassTest, StraightSegmentsThatAreNotParallelAreNoPair) {
  PathGeometry g;
  g.vertices = {{0, 0}, {kRowM, 0}, {kRowM, kRowM}};
  g.edge_segment = {0, 1};
  g.segment_is_turn = {false, false};
  std::vector<TrackSample> t;
  Drive(t, 0, kRowM, 0.5, 0, [](double) { return 0.0; });
  for (int i = 1; i <= 200; ++i) {
    TrackSample s;
    s.t = Time{} + DurationFromSeconds(100 + 0.5 * i);
    s.p_N_m = {kRowM, 0.5 * i};
    s.speed_mps = 1;
    t.push_back(s);
  }
  const PassToPassMetrics m = ScorePassToPass(g, t, PassToPassConfig{});
  EXPECT_EQ(m.passes, 2u);
  EXPECT_TRUE(m.pairs.empty());
}

}  // namespace
}  // namespace hil::harness

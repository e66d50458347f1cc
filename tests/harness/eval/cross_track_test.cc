#include "hil/harness/eval/cross_track.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "hil/harness/eval/outage_metrics.h"

namespace hil::harness {
namespace {

TEST(CrossTrackTest, SignedDistanceToAStraightLine) {
  const PlannedPath p({{0, 0}, {0, 100}});  // due north
  EXPECT_NEAR(p.CrossTrack({-2, 50}), 2.0, 1e-12) << "west of a northbound line is left";
  EXPECT_NEAR(p.CrossTrack({3, 10}), -3.0, 1e-12);
  EXPECT_NEAR(p.CrossTrack({0, 70}), 0.0, 1e-12);
}

TEST(CrossTrackTest, InterpolatesBetweenVerticesInsteadOfUsingTheNearestVertex) {
  // two vertices 100 m apart: a point 1 m off the middle of the segment is 1 m off, although the
  // nearest vertex is more than 50 m away
  const PlannedPath p({{0, 0}, {100, 0}});  // due east
  EXPECT_NEAR(p.CrossTrack({50, 1}), 1.0, 1e-12);
  // a corner: the point is nearest the second segment
  const PlannedPath corner({{0, 0}, {100, 0}, {100, 100}});
  EXPECT_NEAR(corner.CrossTrack({99, 50}), 1.0, 1e-12) << "west of a northbound segment is left";
}

TEST(CrossTrackTest, PlannedPathOfTheScenario) {
  truth::TruthConfig c;
  c.start_p_N_m = {10, 20};
  c.heading_deg = 90;  // east
  c.speed_mps = 1;
  const PlannedPath line = PlannedPathOf(c, 60);
  EXPECT_NEAR(line.CrossTrack({40, 21.5}), 1.5, 1e-9);
  c.steer_deg = 10;  // left circle of radius L / tan(10°)
  const double radius = c.vehicle.wheelbase_m / std::tan(10 * M_PI / 180);
  const PlannedPath circle = PlannedPathOf(c, 600);
  // the centre lies left (north) of an eastbound start; a point on the radius through the start
  // moved 0.5 m towards the centre is 0.5 m left of the path
  EXPECT_NEAR(circle.CrossTrack({10, 20.5}), 0.5, 1e-6);
  // a quarter turn later the vehicle heads north at (10 + R, 20 + R)
  EXPECT_NEAR(circle.CrossTrack({10 + radius + 0.3, 20 + radius}), -0.3, 1e-3);
}

// Every segment in order, the nearest wins (CrossTrack's definition, without pruning).
double ScanAllSegments(const std::vector<Eigen::Vector2d>& v, const Eigen::Vector2d& p) {
  double best_d = std::numeric_limits<double>::infinity(), best_signed = 0;
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    const Eigen::Vector2d ab = v[i + 1] - v[i];
    if (ab.squaredNorm() <= 0) continue;
    const double f = std::clamp((p - v[i]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const double d = (p - (v[i] + f * ab)).norm();
    if (d < best_d) {
      best_d = d;
      best_signed = ab.x() * (p - v[i]).y() - ab.y() * (p - v[i]).x() >= 0 ? d : -d;
    }
  }
  return best_signed;
}

TEST(CrossTrackTest, PrunedScanGivesTheFullScansDistanceBitForBit) {
  // GIVEN a circle of thousands of vertices (constant steering), with a repeated vertex, and
  // points inside, on and outside it
  truth::TruthConfig c;
  c.speed_mps = 1;
  c.steer_deg = 12;
  std::vector<Eigen::Vector2d> v = PlannedPathOf(c, 400).vertices();
  ASSERT_GT(v.size(), 1000u);
  v.insert(v.begin() + 100, v[100]);
  const PlannedPath path(v);
  // THEN CrossTrack, which skips runs of segments that cannot be nearer, agrees with the scan
  for (double x = -30; x <= 30; x += 0.37) {
    for (double y = -45; y <= 15; y += 0.41) {
      const Eigen::Vector2d p(x, y);
      ASSERT_EQ(path.CrossTrack(p), ScanAllSegments(v, p)) << p.transpose();
    }
  }
  for (const Eigen::Vector2d& p : v) ASSERT_EQ(path.CrossTrack(p), ScanAllSegments(v, p));
}

ErrorSample Err(double t_s, double horizontal_m) {
  ErrorSample e;
  e.t = TimeFromSeconds(t_s);
  e.err_enu_m = Eigen::Vector3d(horizontal_m, 0, 0);
  return e;
}

TEST(OutageMetricsTest, GrowthMaximumAndReconvergence) {
  FaultTimeline f;
  Fault o;
  o.kind = FaultKind::kGnssOutage;
  o.start = TimeFromSeconds(10);
  o.end = TimeFromSeconds(20);
  f.faults.push_back(o);
  std::vector<ErrorSample> errors;
  for (int t = 0; t <= 40; ++t) {
    double h = 0.2;
    if (t >= 10 && t <= 20) h = 0.2 + 0.05 * (t - 10) * (t - 10);  // ½ b t² growth
    if (t > 20 && t <= 24) h = 3.0 - 0.6 * (t - 20);               // back down after reacquisition
    errors.push_back(Err(t, h));
  }
  const auto m = ComputeOutages(errors, f, 1.0);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].samples, 11u);
  EXPECT_NEAR(m[0].max_horizontal_error_m, 0.2 + 0.05 * 100, 1e-12);
  ASSERT_FALSE(m[0].growth.empty());
  EXPECT_DOUBLE_EQ(m[0].growth[2].first, 5.0);
  EXPECT_NEAR(m[0].growth[2].second, 0.2 + 0.05 * 25, 1e-12);
  ASSERT_TRUE(m[0].reconvergence_time_s);
  EXPECT_NEAR(*m[0].reconvergence_time_s, 4.0, 1e-12) << "3.0 - 0.6*4 = 0.6 < 1 m first at 24 s";
  // never below threshold: absent
  const auto never = ComputeOutages(errors, f, 0.1);
  EXPECT_FALSE(never[0].reconvergence_time_s);
}

TEST(OutageMetricsTest, DataGapsCountAsOutagesInTimeOrder) {
  FaultTimeline f;
  Fault gap;
  gap.kind = FaultKind::kGnssDataGap;
  gap.start = TimeFromSeconds(5);
  gap.end = TimeFromSeconds(8);
  Fault outage;
  outage.kind = FaultKind::kGnssOutage;
  outage.start = TimeFromSeconds(20);
  outage.end = TimeFromSeconds(25);
  f.faults = {outage, gap};
  std::vector<ErrorSample> errors;
  for (int t = 0; t <= 30; ++t) errors.push_back(Err(t, t >= 5 && t <= 8 ? 0.5 : 0.1));
  const auto m = ComputeOutages(errors, f, 1.0);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_DOUBLE_EQ(m[0].start_s, 5.0);
  EXPECT_NEAR(m[0].max_horizontal_error_m, 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(m[1].start_s, 20.0);
  EXPECT_NEAR(m[1].max_horizontal_error_m, 0.1, 1e-12);
}

TEST(OutageMetricsTest, OutputRateAndMissingSolutions) {
  std::vector<EstimateRecord> r;
  for (int i = 0; i < 100; ++i) {
    if (i >= 50 && i < 60) continue;  // 10 missing of 100 at 10 Hz
    EstimateRecord e;
    e.t_validity = TimeFromSeconds(i * 0.1);
    r.push_back(e);
  }
  const OutputTiming t = ComputeOutputTiming(r, TimeFromSeconds(0), TimeFromSeconds(10), 1.0);
  EXPECT_NEAR(t.output_rate_hz, 90.0 / 10.0, 1e-9);
  EXPECT_NEAR(t.missing_fraction, 10.0 / 100.0, 1e-9);
  EXPECT_FALSE(t.jitter_p50_ms) << "no arrival times, no jitter";
}

// Issue 15.2: a run whose estimator answered 37 of its 120 epochs (it stopped after 37 s) reported
// 1.00 Hz and 0 % missing when only the span between the first and the last solution counted.
TEST(OutageMetricsTest, GapsAtTheStartAndEndOfTheWindowAreMissingSolutions) {
  std::vector<EstimateRecord> r;
  for (int i = 1; i <= 37; ++i) {
    EstimateRecord e;
    e.t_validity = TimeFromSeconds(i);
    r.push_back(e);
  }
  const OutputTiming stops = ComputeOutputTiming(r, TimeFromSeconds(0), TimeFromSeconds(120), 1.0);
  EXPECT_NEAR(stops.output_rate_hz, 37.0 / 120.0, 1e-9);
  EXPECT_NEAR(stops.missing_fraction, 82.0 / 119.0, 1e-9)
      << "the edges count like solutions: 83 s after the last one hold 82 missing";

  for (auto& e : r) e.t_validity += std::chrono::seconds(83);  // the same 37 at 84..120 s
  const OutputTiming late = ComputeOutputTiming(r, TimeFromSeconds(0), TimeFromSeconds(120), 1.0);
  EXPECT_NEAR(late.output_rate_hz, 37.0 / 120.0, 1e-9);
  EXPECT_NEAR(late.missing_fraction, 83.0 / 120.0, 1e-9);

  // records outside the window do not count, and an empty window misses everything
  const OutputTiming outside = ComputeOutputTiming(r, TimeFromSeconds(0), TimeFromSeconds(60), 1.0);
  EXPECT_EQ(outside.output_rate_hz, 0.0);
  EXPECT_EQ(outside.missing_fraction, 1.0);
}

TEST(OutageMetricsTest, AStreamThatFillsTheWindowMissesNothing) {
  std::vector<EstimateRecord> r;
  for (int i = 1; i <= 120; ++i) {  // one epoch per second, the first one second in
    EstimateRecord e;
    e.t_validity = TimeFromSeconds(i);
    r.push_back(e);
  }
  const OutputTiming t = ComputeOutputTiming(r, TimeFromSeconds(0), TimeFromSeconds(120), 1.0);
  EXPECT_NEAR(t.output_rate_hz, 1.0, 1e-12);
  EXPECT_EQ(t.missing_fraction, 0.0);
}

TEST(OutageMetricsTest, ArrivalJitterAroundTheMedianInterval) {
  std::vector<EstimateRecord> r;
  for (int i = 0; i < 100; ++i) {
    EstimateRecord e;
    e.t_validity = TimeFromSeconds(i * 0.1);
    e.wall_rx = WallTimeFromNs(1'000'000'000LL + i * 100'000'000LL +
                               (i % 3 == 0 ? 3'000'000LL : 0));  // every third 3 ms late
    r.push_back(e);
  }
  const OutputTiming t =
      ComputeOutputTiming(r, TimeFromSeconds(0), TimeFromSeconds(10),
                          2.0);  // scaled: wall intervals count double in sim time
  ASSERT_TRUE(t.jitter_max_ms);
  // wall intervals 97, 100, 103 ms (×2 = 194, 200, 206): deviations 6, 0, 6
  EXPECT_NEAR(*t.jitter_p50_ms, 6.0, 1e-6);
  EXPECT_NEAR(*t.jitter_max_ms, 6.0, 1e-6);
}

}  // namespace
}  // namespace hil::harness

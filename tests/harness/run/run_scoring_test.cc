#include "hil/harness/run/run_scoring.h"

#include <stdlib.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/harness/eval/outage_metrics.h"

namespace hil::harness {
namespace {

// A tractor driving north at 1 m/s from the origin for `duration_s`, one 10 s data gap at 100 s.
Scenario StraightNorth(double duration_s) {
  Scenario s;
  s.duration_s = duration_s;
  s.truth.origin = {35.0, 50.0, 100.0};
  s.truth.heading_deg = 0;
  s.truth.speed_mps = 1.0;
  Fault gap;
  gap.kind = FaultKind::kGnssDataGap;
  gap.start = TimeFromSeconds(100);
  gap.end = TimeFromSeconds(110);
  s.faults.faults.push_back(gap);
  return s;
}

// A solution at `t` some centimetres off the straight track (the offset varies with t).
EstimateRecord Solution(const truth::LocalFrame& frame, Time t) {
  const double t_s = ToSeconds(t);
  const double off = 0.02 * std::sin(0.37 * t_s) + 0.01;
  const auto g = frame.ToGeodetic(Eigen::Vector3d(off, t_s + off, -off));
  EstimateRecord r;
  r.t_validity = t;
  r.lat_deg = g.lat_deg;
  r.lon_deg = g.lon_deg;
  r.height_m = g.height_m;
  r.vel_enu_mps = Eigen::Vector3d(0, 1, 0);
  r.pos_std_enu_m = Eigen::Vector3d(0.02, 0.02, 0.03);
  return r;
}

class RunScoringTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/run_scoring_test_XXXXXX";
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  ScoringSetup MakeSetup(const Scenario& s, std::size_t exact_limit) const {
    ScoringSetup setup;
    setup.scenario = &s;
    setup.dir = dir_;
    setup.t_from = Time{};
    setup.t_end = TimeFromSeconds(s.duration_s);
    setup.exact_limit = exact_limit;
    return setup;
  }
  std::string dir_;
};

TEST_F(RunScoringTest, TheMetricsAreThoseOfTheWholeSetScoredAtTheEnd) {
  // GIVEN 300 s of 10 Hz solutions, each handed over 0.3 s after its time, every 50th one 20 s
  // late (out of order, inside the horizon), and 10 Hz fixes
  const Scenario s = StraightNorth(300);
  const truth::LocalFrame frame(s.truth.origin);
  TruthTableBuilder builder(s.truth);
  RunScoring scoring(MakeSetup(s, QuantileSketch::kExactLimit), builder);
  std::vector<EstimateRecord> all, delayed;
  for (int k = 0; k <= 3000; ++k) {
    const Time t = TimeFromNs(k * 100'000'000LL);
    std::vector<EstimateRecord> now;
    if (k >= 3) {
      const EstimateRecord r = Solution(frame, t - std::chrono::milliseconds(300));
      all.push_back(r);
      (k % 50 == 0 ? delayed : now).push_back(r);
    }
    if (k % 200 == 0) {  // the delayed ones come 20 s late
      now.insert(now.end(), delayed.begin(), delayed.end());
      delayed.clear();
    }
    scoring.AddEstimates(now, t);
    scoring.AddFixes({Solution(frame, t)});
    scoring.Advance(t);
  }
  scoring.AddEstimates(delayed, TimeFromSeconds(300));
  scoring.Finish(TimeFromSeconds(300));
  // THEN the metrics, outages and timing are the same bits as the whole set's at the end
  const auto errors = [&] {
    auto e = CompareWithTruth(s.truth, all, Eigen::Vector3d::Zero(), Time{}, TimeFromSeconds(300));
    AddCrossTrack(e, PlannedPathOf(s.truth, s.duration_s));
    return e;
  }();
  const AccuracyMetrics want = ComputeAccuracy(errors), got = scoring.metrics();
  EXPECT_EQ(got.samples, all.size());
  EXPECT_EQ(got.horizontal_rmse_m, want.horizontal_rmse_m);
  EXPECT_EQ(got.cep50_m, want.cep50_m);
  EXPECT_EQ(got.cep95_m, want.cep95_m);
  EXPECT_EQ(got.max_horizontal_error_m, want.max_horizontal_error_m);
  EXPECT_EQ(got.vertical_rmse_m, want.vertical_rmse_m);
  EXPECT_EQ(got.velocity_rmse_mps, want.velocity_rmse_mps);
  EXPECT_EQ(got.cross_track_p95_m, want.cross_track_p95_m);
  EXPECT_EQ(got.nees_mean, want.nees_mean);
  const auto outages = scoring.outages(), want_outages = ComputeOutages(errors, s.faults, 1.0);
  ASSERT_EQ(outages.size(), 1u);
  EXPECT_EQ(outages[0].samples, want_outages[0].samples);
  EXPECT_EQ(outages[0].max_horizontal_error_m, want_outages[0].max_horizontal_error_m);
  EXPECT_EQ(outages[0].growth, want_outages[0].growth);
  const OutputTiming timing = scoring.timing(Time{}, TimeFromSeconds(300));
  const OutputTiming want_timing = ComputeOutputTiming(all, Time{}, TimeFromSeconds(300), 1.0);
  EXPECT_EQ(timing.output_rate_hz, want_timing.output_rate_hz);
  EXPECT_EQ(timing.missing_fraction, want_timing.missing_fraction);
  EXPECT_EQ(scoring.too_late(), 0u);
}

TEST_F(RunScoringTest, ASolutionLaterThanTheHorizonIsCountedNotScored) {
  const Scenario s = StraightNorth(200);
  const truth::LocalFrame frame(s.truth.origin);
  TruthTableBuilder builder(s.truth);
  RunScoring scoring(MakeSetup(s, QuantileSketch::kExactLimit), builder);
  for (int k = 0; k <= 2000; ++k) {
    const Time t = TimeFromNs(k * 100'000'000LL);
    scoring.AddEstimates({Solution(frame, t)}, t);
    scoring.Advance(t);
  }
  // WHEN a solution of t = 10 s arrives at 200 s, 190 s late
  scoring.AddEstimates({Solution(frame, TimeFromSeconds(10))}, TimeFromSeconds(200));
  scoring.Finish(TimeFromSeconds(200));
  EXPECT_EQ(scoring.too_late(), 1u);
  EXPECT_EQ(scoring.metrics().samples, 2001u);
  EXPECT_EQ(scoring.solutions(), 2002u);
}

TEST_F(RunScoringTest, WhatItHoldsIsBoundedWhateverTheRunsLength) {
  // GIVEN a 6000 s run (60 000 solutions, 60 000 fixes, 60 000 rows of truth.csv), each
  // percentile holding 500 values exactly
  const Scenario s = StraightNorth(6000);
  const truth::LocalFrame frame(s.truth.origin);
  TruthTableBuilder builder(s.truth);
  RunScoring scoring(MakeSetup(s, 500), builder);
  // what it holds, at its most over the first half and over the second
  std::size_t first_half = 0, second_half = 0;
  for (int k = 0; k <= 60000; ++k) {
    const Time t = TimeFromNs(k * 100'000'000LL);
    scoring.AddEstimates({Solution(frame, t - std::chrono::milliseconds(200))}, t);
    scoring.AddFixes({Solution(frame, t)});
    scoring.Advance(t);
    if (k % 500 == 0 && k >= 10000) {
      std::size_t& most = k <= 30000 ? first_half : second_half;
      most = std::max(most, scoring.retained());
    }
  }
  scoring.Finish(TimeFromSeconds(6000));
  // THEN twice the run did not hold more (a store of the run would hold 90 000 more), but for
  // what the truth builder's thread can leave pending as it lags (its lag follows the machine's
  // load, held to two horizons by back-pressure: solutions, fixes, their truth times and truth
  // rows, 10 Hz each), and far less than the run's 180 000 records and samples: the plots' points
  // (3 series, at most 3 per bucket), the percentiles' values or buckets, about two horizons of
  // records and times
  const std::size_t lag_allowance =
      2 * 4 * 10 * static_cast<std::size_t>(RunScoring::kLateHorizon / std::chrono::seconds(1));
  EXPECT_LE(second_half, first_half + lag_allowance);
  EXPECT_LE(second_half, 3 * 3 * RunScoring::kPlotBuckets + 8 * 1000 + 12 * 1200);
  EXPECT_EQ(scoring.metrics().samples, 59999u);  // from t = 0
  EXPECT_EQ(scoring.baselines().samples, 60001u);
}

TEST_F(RunScoringTest, AClosedLoopHoldsNoMoreThanAnOpenOneWhateverItsLength) {
  // GIVEN a 6000 s closed loop (issue 40: its truth was sampled at the end, every solution and fix
  // waiting for it, 110 MB per emulated hour): a path north, the actuators commanding 1 m/s every
  // 100 ms, 10 Hz solutions and fixes, each percentile holding 500 values exactly
  Scenario s = StraightNorth(6000);
  s.closed_loop.enabled = true;
  s.closed_loop.path_file = dir_ + "/north.path";
  std::ofstream(s.closed_loop.path_file) << "hil-path 1\nab_line a_m=0,0 b_m=0,10000\n";
  s.truth.external_commands = true;
  s.truth.command_period_s = 0.1;
  const truth::LocalFrame frame(s.truth.origin);
  TruthTableBuilder builder(s.truth);
  RunScoring scoring(MakeSetup(s, 500), builder);
  std::size_t first_half = 0, second_half = 0;
  for (int k = 0; k <= 60000; ++k) {
    const Time t = TimeFromNs(k * 100'000'000LL);
    builder.Command({t, 1.0, 0.0});
    scoring.AddEstimates({Solution(frame, t - std::chrono::milliseconds(200))}, t);
    scoring.AddFixes({Solution(frame, t)});
    scoring.Advance(t);
    if (k % 500 == 0 && k >= 10000) {
      std::size_t& most = k <= 30000 ? first_half : second_half;
      most = std::max(most, scoring.retained());
    }
  }
  const TruthTable rest = scoring.Finish(TimeFromSeconds(6000));
  // THEN it holds what the open loop holds (WhatItHoldsIsBoundedWhateverTheRunsLength), scored as
  // it went: no solution, fix or truth sample kept to the end; what the lagging truth thread can
  // leave pending is one series more than the open loop's, the commands (10 Hz, waiting for the
  // thread as the truth times do; stop 53's CI saw 136 beyond four series' allowance)
  const std::size_t lag_allowance =
      2 * 4 * 10 * static_cast<std::size_t>(RunScoring::kLateHorizon / std::chrono::seconds(1));
  const std::size_t command_lag_allowance =
      2 * 10 * static_cast<std::size_t>(RunScoring::kLateHorizon / std::chrono::seconds(1));
  EXPECT_LE(second_half, first_half + lag_allowance + command_lag_allowance);
  EXPECT_LE(second_half, 3 * 3 * RunScoring::kPlotBuckets + 8 * 1000 + 12 * 1200);
  EXPECT_LE(rest.times().size(), lag_allowance);  // the last horizon, sampled at the end
  EXPECT_EQ(scoring.metrics().samples, 59999u);
  EXPECT_EQ(scoring.baselines().samples, 60001u);
  EXPECT_EQ(builder.stale_samples(), 0u);
  // AND the truth obeyed the commands: 1 m/s north for 6000 s, less the speed lag's start
  ASSERT_EQ(scoring.track().size(), 60001u);
  EXPECT_NEAR(scoring.track().back().p_N_m.y(), 6000.0, 5.0);
}

}  // namespace
}  // namespace hil::harness

#include "hil/harness/run/truth_table.h"

#include <chrono>
#include <vector>

#include <gtest/gtest.h>

#include "../truth/truth_test_scenarios.h"

namespace hil::harness {
namespace {

// Bit for bit: the fields the evaluation and truth.csv read.
void ExpectSameSample(const TruthSample& a, const TruthSample& b) {
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.lat_deg, b.lat_deg);
  EXPECT_EQ(a.lon_deg, b.lon_deg);
  EXPECT_EQ(a.height_m, b.height_m);
  EXPECT_EQ(a.p_NB_N_m, b.p_NB_N_m);
  EXPECT_EQ(a.v_NB_N_mps, b.v_NB_N_mps);
  EXPECT_EQ(a.q_NB.coeffs(), b.q_NB.coeffs());
  EXPECT_EQ(a.w_IB_B_radps, b.w_IB_B_radps);
  EXPECT_EQ(a.f_B_mps2, b.f_B_mps2);
  EXPECT_EQ(a.cross_track_m, b.cross_track_m);
}

TEST(TruthTableBuilderTest, OfferedSamplesServeTheirTimesAndTheThreadIntegratesTheRest) {
  // GIVEN the rough-ground rectangle, a run that samples its truth at 100 Hz and offers every
  // sample, and a table asked for the 10 Hz grid plus times between the run's samples
  const truth::TruthConfig config = truth::testing::RoughTurningConfig();
  std::vector<Time> grid, between;
  for (int k = 0; k <= 200; ++k) grid.push_back(TimeFromNs(k * 100'000'000LL));
  for (int k = 0; k < 20; ++k) between.push_back(TimeFromNs(k * 1'000'000'000LL + 3'000'000));
  TruthTableBuilder builder(config);
  builder.Ask(grid);
  builder.Ask(between);
  // WHEN the run goes on, its samples offered and the watermark a second behind
  truth::TruthIntegrator run(config);
  for (int k = 0; k <= 2000; ++k) {
    const Time t = TimeFromNs(k * 10'000'000LL);
    builder.Offer(run.Sample(t));
    if (k % 50 == 0) builder.Advance(t - std::chrono::seconds(1));
  }
  const TruthTable table = builder.Finish();
  // THEN every time is there, as a fresh integration gives it, and only the times between the
  // run's samples were integrated again
  std::vector<Time> all = grid;
  all.insert(all.end(), between.begin(), between.end());
  const TruthTable fresh(config, all);
  for (const Time t : all) {
    ASSERT_TRUE(table.Has(t));
    ExpectSameSample(table.At(t), fresh.At(t));
  }
  EXPECT_EQ(builder.offered_hits(), grid.size());
  EXPECT_EQ(builder.integrated(), between.size());
}

TEST(TruthTableBuilderTest, WithoutOffersTheThreadIntegratesEveryTime) {
  const truth::TruthConfig config = truth::testing::RoughTurningConfig();
  std::vector<Time> times;
  for (int k = 0; k <= 50; ++k) times.push_back(TimeFromNs(k * 100'000'000LL));
  TruthTableBuilder builder(config);
  builder.Ask(times);
  builder.Advance(TimeFromNs(3'000'000'000LL));
  const TruthTable table = builder.Finish();
  const TruthTable fresh(config, times);
  for (const Time t : times) ExpectSameSample(table.At(t), fresh.At(t));
  EXPECT_EQ(builder.offered_hits(), 0u);
  EXPECT_EQ(builder.integrated(), times.size());
}

}  // namespace
}  // namespace hil::harness

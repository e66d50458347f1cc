#include "hil/harness/run/truth_table.h"

#include <chrono>
#include <vector>

#include <gtest/gtest.h>

#include "../truth/truth_test_scenarios.h"
#include "expect_same_sample.h"

namespace hil::harness {
namespace {

using testing::ExpectSameSample;

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

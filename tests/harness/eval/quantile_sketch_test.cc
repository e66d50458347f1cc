#include "hil/harness/core/quantile_sketch.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hil/harness/eval/evaluator.h"
#include "hil/harness/eval/series_decimator.h"

namespace hil::harness {
namespace {

std::vector<double> LogNormalValues(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::lognormal_distribution<double> d(-3.0, 1.0);  // errors of a few cm, a long tail
  std::vector<double> v(n);
  for (double& x : v) x = d(rng);
  return v;
}

TEST(QuantileSketchTest, UpToItsLimitAPercentileIsThePercentileOfAllValues) {
  const std::vector<double> v = LogNormalValues(5000, 1);
  QuantileSketch q(5000);
  for (const double x : v) q.Add(x);
  ASSERT_TRUE(q.exact());
  for (const double pct : {0.0, 50.0, 95.0, 99.0, 100.0})
    EXPECT_EQ(q.Percentile(pct), Percentile(v, pct)) << pct << ": the same bits";
}

TEST(QuantileSketchTest, PastItsLimitAPercentileIsWithinTheRelativeAccuracy) {
  const std::vector<double> v = LogNormalValues(200000, 2);
  QuantileSketch q(1000);
  for (const double x : v) q.Add(x);
  ASSERT_FALSE(q.exact());
  for (const double pct : {1.0, 50.0, 95.0, 99.0}) {
    const double exact = Percentile(v, pct);
    EXPECT_NEAR(q.Percentile(pct), exact, exact * QuantileSketch::kRelativeAccuracy * 1.01) << pct;
  }
  EXPECT_EQ(q.Percentile(100), Percentile(v, 100)) << "the largest value is kept exactly";
  EXPECT_EQ(q.Percentile(0), Percentile(v, 0)) << "and the smallest";
}

TEST(QuantileSketchTest, ItsExactValuesWaitOnDiskAndStayExact) {
  // GIVEN the default sketch (2^18 values exact) and 200 000 values (5.6 h of 10 Hz solutions)
  QuantileSketch q;
  std::mt19937_64 rng(11);
  std::lognormal_distribution<double> d(-3.0, 1.0);
  std::vector<double> v;
  for (int i = 0; i < 200'000; ++i) {
    v.push_back(d(rng));
    q.Add(v.back());
  }
  // THEN at most a spill file's tail of them is in memory (issue 40: every one was, 2 MiB a set)
  EXPECT_TRUE(q.exact());
  EXPECT_LE(q.retained(), SpillFile<double>::kMemoryItems);
  // AND the percentiles are those of all the values, bit for bit; a copy has them too
  const QuantileSketch copy = q;
  for (const double pct : {0.0, 50.0, 95.0, 99.0, 100.0}) {
    EXPECT_EQ(q.Percentile(pct), Percentile(v, pct)) << pct;
    EXPECT_EQ(copy.Percentile(pct), Percentile(v, pct)) << pct;
  }
}

TEST(QuantileSketchTest, WhatItHoldsDoesNotGrowWithTheNumberOfValues) {
  // GIVEN a sketch that holds 1000 values exactly
  QuantileSketch q(1000);
  std::mt19937_64 rng(3);
  std::lognormal_distribution<double> d(-3.0, 1.0);
  std::size_t at_1e5 = 0;
  // WHEN five million values of the same distribution come
  for (std::size_t i = 1; i <= 5'000'000; ++i) {
    q.Add(d(rng));
    if (i == 100'000) at_1e5 = q.retained();
  }
  // THEN it holds no more buckets than the range of the values needs, as after 1e5 values
  EXPECT_EQ(q.count(), 5'000'000u);
  EXPECT_LT(q.retained(), 10'000u);
  EXPECT_LT(q.retained(), at_1e5 + at_1e5 / 2);
}

// replay merges its links' schedule errors (replay.h): the percentiles of both sets' values, exact
// while they fit, within the accuracy when either sketches (negative errors included: early bytes)
TEST(QuantileSketchTest, AMergeHasThePercentilesOfBothSets) {
  std::vector<double> a = LogNormalValues(3000, 4), b = LogNormalValues(150000, 5);
  for (std::size_t i = 0; i < b.size(); i += 7) b[i] = -b[i];
  QuantileSketch small_a(5000), small_b(5000), big_a(1000), big_b(1000);
  for (const double x : a) small_a.Add(x), big_a.Add(x);
  for (const double x : std::vector<double>(b.begin(), b.begin() + 1500)) small_b.Add(x);
  for (const double x : b) big_b.Add(x);
  std::vector<double> exact_both = a;
  exact_both.insert(exact_both.end(), b.begin(), b.begin() + 1500);
  small_a.Merge(small_b);
  ASSERT_TRUE(small_a.exact());
  EXPECT_EQ(small_a.count(), exact_both.size());
  for (const double pct : {0.0, 50.0, 99.0, 100.0})
    EXPECT_EQ(small_a.Percentile(pct), Percentile(exact_both, pct)) << pct;
  std::vector<double> all = a;
  all.insert(all.end(), b.begin(), b.end());
  big_a.Merge(big_b);
  ASSERT_FALSE(big_a.exact());
  EXPECT_EQ(big_a.count(), all.size());
  EXPECT_EQ(big_a.min(), Percentile(all, 0));
  EXPECT_EQ(big_a.max(), Percentile(all, 100));
  for (const double pct : {1.0, 10.0, 50.0, 95.0, 99.0}) {
    const double exact = Percentile(all, pct);
    EXPECT_NEAR(big_a.Percentile(pct), exact,
                std::abs(exact) * QuantileSketch::kRelativeAccuracy * 1.01)
        << pct;
  }
}

TEST(QuantileSketchTest, TheCdfHasAtMostTheNumberOfPointsAsked) {
  QuantileSketch q;
  for (const double x : LogNormalValues(100000, 4)) q.Add(x);
  const auto cdf = CdfPoints(q, 500);
  ASSERT_LE(cdf.size(), 501u);
  EXPECT_EQ(cdf.front().first, q.min());
  EXPECT_EQ(cdf.back().first, q.max());
  EXPECT_DOUBLE_EQ(cdf.back().second, 100.0);
  for (std::size_t i = 1; i < cdf.size(); ++i) EXPECT_GE(cdf[i].second, cdf[i - 1].second);
}

TEST(SeriesDecimatorTest, KeepsEverySampleOfAShortSeriesAndTheSpikesOfALongOne) {
  // a short series: every item
  SeriesDecimator<double> shortd(100, 0.01);
  for (int i = 0; i < 50; ++i) shortd.Add(i * 0.1, 0, i);
  EXPECT_EQ(shortd.Points().size(), 50u);
  // GIVEN ten million 10 Hz samples (a 11.6-day run) with one spike
  SeriesDecimator<double> d(512, 0.01);
  for (std::size_t i = 0; i < 10'000'000; ++i) {
    const double v = i == 7'654'321 ? 99.0 : 0.01 * static_cast<double>(i % 7);
    d.Add(static_cast<double>(i) * 0.1, v, v);
  }
  // THEN at most three items per bucket are held, and the spike is among them
  EXPECT_LE(d.retained(), 3u * 512u);
  const std::vector<double> p = d.Points();
  EXPECT_LE(p.size(), 3u * 512u);
  EXPECT_NE(std::find(p.begin(), p.end(), 99.0), p.end());
}

}  // namespace
}  // namespace hil::harness

// The k-th smallest value of a set read in passes (the tracking figures' exact percentiles over
// values on disk): the value std::nth_element gives, for small sets (in memory) and large ones
// (narrowed by the keys' digits), with negative values, zeros and repeated values; and how many
// passes it takes.
#include "hil/harness/eval/exact_selection.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

ValuePass PassOf(const std::vector<double>& v, int& passes) {
  return [&v, &passes](const ValueVisit& visit) {
    ++passes;
    for (const double x : v) visit(x);
  };
}

double Expected(std::vector<double> v, std::size_t k) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

TEST(ExactSelectionTest, TheRankOfASmallSetInOnePass) {
  const std::vector<double> v{3.5, -1.0, 0.0, 2.25, -7.5, 3.5, 1e-300};
  for (std::size_t k = 0; k < v.size(); ++k) {
    int passes = 0;
    EXPECT_EQ(KthSmallest(v.size(), k, PassOf(v, passes)), Expected(v, k)) << k;
    EXPECT_EQ(passes, 1);
  }
}

TEST(ExactSelectionTest, TheRankOfALargeSetIsExactInFewPasses) {
  // GIVEN 200 000 values: most near 0.01 (a tracking error's scale), negatives, repeats, zeros
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 0.01);
  std::vector<double> v(200000);
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i] = i % 97 == 0 ? 0.0 : i % 89 == 0 ? 0.125 : normal(rng);
  }
  for (const std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{100000},
                              std::size_t{189999}, std::size_t{190000}, v.size() - 1}) {
    int passes = 0;
    EXPECT_EQ(KthSmallest(v.size(), k, PassOf(v, passes)), Expected(v, k)) << k;
    EXPECT_LE(passes, 7);
    EXPECT_GE(passes, 2);  // narrowed first: more than the 8192 it selects in memory
  }
}

TEST(ExactSelectionTest, ASetOfOneRepeatedValueNeedsEveryDigit) {
  const std::vector<double> v(50000, 0.3);
  int passes = 0;
  EXPECT_EQ(KthSmallest(v.size(), 47500, PassOf(v, passes)), 0.3);
  EXPECT_EQ(passes, 6);  // 64 bits at 12 a pass, every value a candidate to the last
}

TEST(ExactSelectionTest, TheNearestRankP95) {
  std::vector<double> v;
  for (int i = 1; i <= 100; ++i) v.push_back(i);
  int passes = 0;
  EXPECT_EQ(NearestRankP95(v.size(), PassOf(v, passes)), 95.0);
  EXPECT_EQ(NearestRankP95(0, PassOf(v, passes)), 0.0);
  const std::vector<double> one{4.0};
  EXPECT_EQ(NearestRankP95(1, PassOf(one, passes)), 4.0);
}

}  // namespace
}  // namespace hil::harness

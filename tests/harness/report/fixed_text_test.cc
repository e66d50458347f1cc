// AppendFixed (fixed_text.h): the characters printf's "%.Nf" writes, for the values a run folder
// holds and for the edges (ties, negative zero, rounding to zero, not-a-number, the very large).
#include "hil/harness/report/fixed_text.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

std::string Printf(double v, int decimals) {
  char b[512];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

std::string Fixed(double v, int decimals) {
  std::string s = "x";
  AppendFixed(s, v, decimals);
  return s.substr(1);
}

TEST(FixedTextTest, WritesPrintfsDigitsForRandomValuesAndEveryPrecision) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, 9);
  for (int i = 0; i < 200000; ++i) {
    const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
    const int decimals = i % 13;
    ASSERT_EQ(Fixed(v, decimals), Printf(v, decimals)) << v << " with " << decimals;
  }
}

TEST(FixedTextTest, WritesPrintfsDigitsAtTheEdges) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double v : {0.0, -0.0, 0.125, 0.375, 2.5, -2.5, 1e-7, -1e-7, 0.5, 1.5, 1e15 + 0.5,
                         123456789.123456789, inf, -inf, nan, -nan, 1e300, -1e300}) {
    for (const int decimals : {0, 1, 2, 3, 6, 10}) {
      EXPECT_EQ(Fixed(v, decimals), Printf(v, decimals)) << v << " with " << decimals;
    }
  }
}

TEST(FixedTextTest, TheMostDecimalsOfTheLargestValueFitAndMoreAreRefused) {
  const double big = -std::numeric_limits<double>::max();
  EXPECT_EQ(Fixed(big, kMaxDecimals), Printf(big, kMaxDecimals));
  std::string s;
  EXPECT_THROW(AppendFixed(s, 1.0, kMaxDecimals + 1), std::out_of_range);
  EXPECT_THROW(AppendFixed(s, 1.0, -1), std::out_of_range);
}

TEST(FixedTextTest, AppendFixedRowSeparatesWithCommas) {
  std::string s = "t,";
  AppendFixedRow(s, 3, 1.0, -2.0005, 3.25);
  EXPECT_EQ(s, "t," + Printf(1.0, 3) + "," + Printf(-2.0005, 3) + "," + Printf(3.25, 3));
}

}  // namespace
}  // namespace hil::harness

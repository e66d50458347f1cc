#include "hil/estimator/datasets/fixed_decimal.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

namespace hil::estimator::datasets {
namespace {

std::string Ours(double v, int decimals) {
  char buf[400];
  return {buf, FormatFixed(buf, buf + sizeof buf, v, decimals)};
}

std::string Std(double v, int decimals) {
  char buf[400];
  return {buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals).ptr};
}

TEST(FormatFixed, GivesToCharsBytesForTheColumnsNavdWrites) {
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double scales[] = {1e-9, 1e-3, 1.0, 30.0, 180.0, 1e3, 6e5, 1e7};
  int checked = 0;
  for (int k = 0; k < 200000; ++k) {
    const double v = unit(rng) * scales[k % 8];
    for (int d = 0; d <= 12; ++d) {  // every count has its own digit writer
      ASSERT_EQ(Ours(v, d), Std(v, d)) << "v=" << v << " decimals=" << d;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2600000);
}

TEST(FormatFixed, EdgeCases) {
  const double inf = std::numeric_limits<double>::infinity();
  for (const double v : {0.0,
                         -0.0,
                         -1e-20,
                         0.5,
                         1.5,
                         2.5,
                         -2.5,
                         0.125,
                         0.375,
                         1e15,
                         3.9999e15,
                         4e15,
                         1e300,
                         -1e300,
                         inf,
                         -inf,
                         std::nan(""),
                         9.9999999999995,
                         0.000000499999,
                         0.0000005,
                         456300.005,
                         30.52780003906}) {
    for (int d = 0; d <= 17; ++d) EXPECT_EQ(Ours(v, d), Std(v, d)) << "v=" << v << " d=" << d;
  }
  EXPECT_EQ(Ours(-0.0, 3), "-0.000");
  EXPECT_EQ(Ours(2.5, 0), Std(2.5, 0));  // a tie: to_chars's own rounding
  char small[4];
  EXPECT_EQ(FormatFixed(small, small + sizeof small, 123.456, 3), small);  // does not fit
}

}  // namespace
}  // namespace hil::estimator::datasets

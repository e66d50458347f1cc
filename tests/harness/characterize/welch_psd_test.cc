// Welch PSD: white noise level, Parseval, a tone in its bin; the PSD's white-noise read-out.
#include "hil/harness/characterize/welch_psd.h"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "hil/harness/characterize/noise_fit.h"

namespace hil::harness {
namespace {

std::vector<double> WhiteNoise(std::size_t n, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, sigma);
  std::vector<double> y(n);
  for (double& v : y) v = g(rng);
  return y;
}

TEST(WelchPsdTest, WhiteNoiseHasTheOneSidedLevelTwoSigmaSquaredOverFs) {
  const double fs = 200, sigma = 0.3;
  const std::vector<double> y = WhiteNoise(1 << 17, sigma, 5);
  const Psd p = WelchPsd(y, fs, 1024);
  EXPECT_EQ(p.freq_hz.size(), 513u);
  EXPECT_DOUBLE_EQ(p.freq_hz.back(), fs / 2);
  EXPECT_EQ(p.segments, (y.size() - 1024) / 512 + 1);
  double sum = 0;
  for (std::size_t k = 1; k + 1 < p.density.size(); ++k) sum += p.density[k];
  EXPECT_NEAR(sum / static_cast<double>(p.density.size() - 2) / (2 * sigma * sigma / fs), 1.0,
              0.02);
  // and N read from the PSD is σ·√τ0
  EXPECT_NEAR(WhiteNoiseFromPsd(p.freq_hz, p.density, fs / 50, fs / 10) / (sigma / std::sqrt(fs)),
              1.0, 0.03);
}

TEST(WelchPsdTest, IntegratesToTheVarianceAndPutsATonePeakInItsBin) {
  const double fs = 100, f0 = 12.5, amp = 2.0;
  std::vector<double> y = WhiteNoise(1 << 15, 0.1, 6);
  for (std::size_t k = 0; k < y.size(); ++k)
    y[k] += amp * std::sin(2 * std::numbers::pi * f0 * static_cast<double>(k) / fs);
  const Psd p = WelchPsd(y, fs, 512);
  double integral = 0;
  std::size_t peak = 0;
  for (std::size_t k = 0; k < p.density.size(); ++k) {
    integral += p.density[k] * fs / 512;
    if (p.density[k] > p.density[peak]) peak = k;
  }
  EXPECT_NEAR(integral / (amp * amp / 2 + 0.01), 1.0, 0.03);
  EXPECT_DOUBLE_EQ(p.freq_hz[peak], f0);
}

TEST(WelchPsdTest, RejectsOddOrOverlongSegments) {
  EXPECT_THROW(WelchPsd(std::vector<double>(100), 1, 15), std::invalid_argument);
  EXPECT_THROW(WelchPsd(std::vector<double>(100), 1, 128), std::invalid_argument);
  EXPECT_EQ(DefaultWelchSegment(100), 16u);
  EXPECT_EQ(DefaultWelchSegment(1 << 20), 4096u);
  EXPECT_EQ(DefaultWelchSegment(20000), 2048u);
}

}  // namespace
}  // namespace hil::harness

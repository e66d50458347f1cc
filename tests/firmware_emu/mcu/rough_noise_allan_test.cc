// The issue-41 noise terms by their Allan-deviation slopes, computed in the test (allan.h): white
// noise falls as τ^−1/2, rate random walk rises as τ^+1/2, and the flicker sum of Gauss–Markov
// processes is flat (slope ≈ 0) at B·√(2 ln2/π) across the band of its correlation times.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/mcu/sensor_spec.h"
#include "hil/firmware_emu/mcu/sensor_triad.h"

#include "allan.h"

namespace hil::mcu {
namespace {

constexpr double kDegR = std::numbers::pi / 180.0;
constexpr double kDtR = 0.1;

TriadSpec Quiet() {
  TriadSpec s;
  s.sampling = Sampling::kAverage;
  return s;
}

std::vector<double> StillX(const TriadSpec& spec, std::size_t n, std::uint64_t seed) {
  SensorTriad t(spec, kDtR, seed);
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k)
    x[k] = t.MeasureBandLimited(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 25.0)[0];
  return x;
}

// log-log slope of the Allan deviation between the points nearest τ0 and τ1
double Slope(const std::vector<std::pair<double, double>>& a, double tau0, double tau1) {
  auto nearest = [&](double tau) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (std::abs(std::log(a[i].first / tau)) < std::abs(std::log(a[best].first / tau))) best = i;
    return a[best];
  };
  const auto p0 = nearest(tau0), p1 = nearest(tau1);
  return std::log(p1.second / p0.second) / std::log(p1.first / p0.first);
}

TEST(RoughNoiseAllanTest, WhiteNoiseFallsAsMinusOneHalf) {
  TriadSpec s = Quiet();
  s.error.noise_density = Eigen::Vector3d::Constant(0.0028 * kDegR);  // ICM-42688 class
  const auto a = test::AllanDeviation(StillX(s, 200000, 1), kDtR);
  EXPECT_NEAR(Slope(a, 0.1, 100), -0.5, 0.05);
  EXPECT_NEAR(test::NoiseDensityFromAllan(a) / s.error.noise_density[0], 1.0, 0.05);
}

TEST(RoughNoiseAllanTest, RateRandomWalkRisesAsPlusOneHalf) {
  TriadSpec s = Quiet();
  s.error.bias_random_walk = 1e-5;  // unit/√s
  const auto a = test::AllanDeviation(StillX(s, 400000, 2), kDtR);
  EXPECT_NEAR(Slope(a, 10, 1000), 0.5, 0.1);
  // σ(τ) = K·√(τ/3)
  double k_hat = 0;
  for (const auto& [tau, sigma] : a)
    if (tau > 50 && tau < 200) k_hat = sigma / std::sqrt(tau / 3.0);
  EXPECT_NEAR(k_hat / 1e-5, 1.0, 0.25);
}

TEST(RoughNoiseAllanTest, FlickerSumIsFlatAtTheBiasInstabilityFloor) {
  TriadSpec s = Quiet();
  const double b = 5.0 * kDegR / 3600.0;  // 5 °/h
  s.error.bias_instability = b;
  s.error.flicker_terms = 3;
  s.error.flicker_tau_min_s = 2;
  s.error.flicker_tau_max_s = 200;
  const double floor = b * std::sqrt(2.0 * std::numbers::ln2 / std::numbers::pi);
  // the mean Allan deviation of three seeds, against the floor, inside the band
  std::vector<std::pair<double, double>> mean;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto a = test::AllanDeviation(StillX(s, 600000, seed), kDtR);
    if (mean.empty()) mean.assign(a.size(), {0.0, 0.0});
    for (std::size_t i = 0; i < a.size(); ++i)
      mean[i] = {a[i].first, mean[i].second + a[i].second / 3};
  }
  EXPECT_NEAR(Slope(mean, 6.4, 204.8), 0.0, 0.15);
  double worst = 0;
  for (const auto& [tau, sigma] : mean) {
    if (tau < 3.2 || tau > 410) continue;
    std::printf("tau %.1f s: sigma/floor %.3f\n", tau, sigma / floor);
    worst = std::max(worst, std::abs(sigma / floor - 1.0));
  }
  EXPECT_LT(worst, 0.25);
}

TEST(RoughNoiseAllanTest, GaussMarkovAllanVariancePeaksAtTheKnownPoint) {
  // σ_A peaks at 0.6174 σ at τ = 1.89 τc
  EXPECT_NEAR(std::sqrt(GaussMarkovAllanVariance(1.8926, 1.0)), 0.6174, 1e-3);
  EXPECT_LT(GaussMarkovAllanVariance(1.5, 1.0), GaussMarkovAllanVariance(1.8926, 1.0));
  EXPECT_LT(GaussMarkovAllanVariance(2.5, 1.0), GaussMarkovAllanVariance(1.8926, 1.0));
}

TEST(RoughNoiseAllanTest, SameSeedSameRecord) {
  TriadSpec s = Quiet();
  s.error.noise_density = Eigen::Vector3d::Constant(1e-3);
  s.error.bias_instability = 1e-4;
  s.error.flicker_terms = 3;
  EXPECT_EQ(StillX(s, 1000, 5), StillX(s, 1000, 5));
  EXPECT_NE(StillX(s, 1000, 5), StillX(s, 1000, 6));
}

}  // namespace
}  // namespace hil::mcu

// Noise terms read off Allan curves: analytic curves (exact terms known) and synthetic noise.
#include "hil/harness/characterize/noise_fit.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "hil/harness/characterize/allan_deviation.h"

namespace hil::harness {
namespace {

std::vector<double> Octaves(double tau0, int count) {
  std::vector<double> t;
  for (int k = 0; k < count; ++k) t.push_back(tau0 * std::pow(2.0, k));
  return t;
}

TEST(NoiseFitTest, ReadsWhiteFloorAndRandomWalkOffAnAnalyticCurve) {
  // GIVEN σ²(τ) = N²/τ + (0.664 B)² + K² τ/3 with the three regions decades apart
  const double n = 1e-4, b = 2e-5, k = 1e-7;
  const std::vector<double> tau = Octaves(0.005, 28);
  std::vector<double> adev;
  for (double t : tau)
    adev.push_back(std::sqrt(n * n / t + std::pow(kBiasInstabilityFloor * b, 2) + k * k * t / 3));
  const NoiseTerms r = FitNoiseTerms(tau, adev);
  EXPECT_NEAR(r.white / n, 1.0, 0.01);
  EXPECT_NEAR(r.white_slope, -0.5, 0.01);
  EXPECT_TRUE(r.bias_instability_resolved);
  EXPECT_NEAR(r.bias_instability / b, 1.0, 0.1);  // the floor sits a little above 0.664 B
  ASSERT_TRUE(r.rate_random_walk.has_value());
  EXPECT_NEAR(*r.rate_random_walk / k, 1.0, 0.1);
}

TEST(NoiseFitTest, WhiteNoiseOnlyGivesAnUnresolvedBiasBound) {
  const double tau0 = 0.01, sigma = 0.01;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g(0, sigma);
  std::vector<double> y(1 << 16);
  for (double& v : y) v = g(rng);
  const std::vector<std::size_t> m = OctaveClusterSizes(y.size());
  std::vector<double> tau;
  for (std::size_t k : m) tau.push_back(static_cast<double>(k) * tau0);
  const NoiseTerms r = FitNoiseTerms(tau, OverlappingAllanDeviation(y, tau0, m));
  EXPECT_NEAR(r.white / (sigma * std::sqrt(tau0)), 1.0, 0.05);
  EXPECT_FALSE(r.rate_random_walk.has_value());
}

TEST(NoiseFitTest, FallingCurveToTheEndIsABoundNotAFloor) {
  const std::vector<double> tau = Octaves(0.01, 8);
  std::vector<double> adev;
  for (double t : tau) adev.push_back(1e-3 / std::sqrt(t));
  const NoiseTerms r = FitNoiseTerms(tau, adev);
  EXPECT_FALSE(r.bias_instability_resolved);
  EXPECT_NEAR(r.bias_instability, adev.back() / kBiasInstabilityFloor, 1e-15);
}

TEST(NoiseFitTest, RejectsTooFewPoints) {
  EXPECT_THROW(FitNoiseTerms({1.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(FitNoiseTerms({1.0, 2.0}, {1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace hil::harness

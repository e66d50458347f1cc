// Noise terms read off Allan curves: analytic curves (exact terms known) and synthetic noise.
#include "hil/harness/characterize/noise_fit.h"

#include <algorithm>
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

TEST(NoiseFitTest, AGaussMarkovBumpDoesNotHideTheFirstFloor) {
  // GIVEN white noise N and a first-order Gauss–Markov bias (σ_b, T): the curve falls, turns up
  // into the bias's bump near 1.89 T and falls again as 1/√τ beyond it, lower than the first floor
  const double n = 1e-3, sigma_b = 3e-4, t_c = 100;
  const std::vector<double> tau = Octaves(0.01, 25);
  std::vector<double> adev;
  for (double t : tau) {
    const double q2 = 2 * sigma_b * sigma_b / t_c;  // GM Allan variance (IEEE Std 952 annex C)
    const double gm = q2 * t_c * t_c / t *
                      (1 - t_c / (2 * t) * (3 - 4 * std::exp(-t / t_c) + std::exp(-2 * t / t_c)));
    adev.push_back(std::sqrt(n * n / t + gm));
  }
  ASSERT_LT(adev.back(), *std::min_element(adev.begin(), adev.begin() + 15));
  const NoiseTerms r = FitNoiseTerms(tau, adev);
  // THEN the floor is the valley before the bump, not the tail's last point
  EXPECT_TRUE(r.bias_instability_resolved);
  EXPECT_LT(r.bias_instability_tau_s, t_c);
  EXPECT_NEAR(r.white / n, 1.0, 0.02);
  const auto it = std::find(tau.begin(), tau.end(), r.bias_instability_tau_s);
  const auto i = static_cast<std::size_t>(it - tau.begin());
  EXPECT_LT(adev[i], adev[i - 1]);
  EXPECT_LE(adev[i], adev[i + 1]);
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

TEST(NoiseFitTest, AnInitialRiseIsSkipped) {
  // GIVEN a tone that lifts the shortest τ before the white decline (as walk_0827's 17.5 Hz)
  const std::vector<double> tau = Octaves(0.01, 10);
  std::vector<double> adev;
  for (double t : tau) adev.push_back(1e-3 / std::sqrt(t));
  adev[0] = 0.5 * adev[2];
  adev[1] = 0.8 * adev[2];
  const NoiseTerms r = FitNoiseTerms(tau, adev);
  EXPECT_GE(r.white_tau_s, tau[2]);
  EXPECT_NEAR(r.white, 1e-3, 1e-12);
  EXPECT_EQ(r.bias_instability_tau_s, tau.back());
  EXPECT_FALSE(r.bias_instability_resolved);
}

TEST(NoiseFitTest, RejectsTooFewPoints) {
  EXPECT_THROW(FitNoiseTerms({1.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(FitNoiseTerms({1.0, 2.0}, {1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace hil::harness

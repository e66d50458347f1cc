// The overlapping Allan deviation (cumulative sums) against analytic curves of synthetic noise and
// against an independent computation from the definition (cluster averages, direct summation).
#include "hil/harness/characterize/allan_deviation.h"

#include <cmath>
#include <filesystem>
#include <random>

#include <gtest/gtest.h>

#include "hil/harness/characterize/characterize.h"
#include "hil/harness/characterize/imu_log_readers.h"

namespace hil::harness {
namespace {

// σ(mτ0) from the definition: ȳ_k = mean of y_k..y_{k+m−1}; σ² = ½ mean over k of (ȳ_{k+m} − ȳ_k)²,
// every cluster average summed directly (O(N·m), no cumulative sum)
double DirectAllanDeviation(const std::vector<double>& y, std::size_t m) {
  const std::size_t pairs = y.size() - 2 * m + 1;
  long double sum = 0;
  for (std::size_t k = 0; k < pairs; ++k) {
    long double a = 0, b = 0;
    for (std::size_t i = 0; i < m; ++i) {
      a += y[k + i];
      b += y[k + m + i];
    }
    const long double d = (b - a) / static_cast<long double>(m);
    sum += d * d;
  }
  return std::sqrt(static_cast<double>(sum / pairs / 2));
}

std::vector<double> WhiteNoise(std::size_t n, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, sigma);
  std::vector<double> y(n);
  for (double& v : y) v = g(rng);
  return y;
}

TEST(AllanDeviationTest, OctaveClusterSizesStopAtAQuarterOfTheSamples) {
  EXPECT_EQ(OctaveClusterSizes(3), std::vector<std::size_t>{});
  EXPECT_EQ(OctaveClusterSizes(64), (std::vector<std::size_t>{1, 2, 4, 8, 16}));
  EXPECT_EQ(OctaveClusterSizes(70), (std::vector<std::size_t>{1, 2, 4, 8, 16}));
}

TEST(AllanDeviationTest, WhiteNoiseFollowsNOverRootTau) {
  // GIVEN white rate noise of density N = σ_w·√τ0 at τ0 = 10 ms
  const double tau0 = 0.01, sigma_w = 0.02, n_density = sigma_w * std::sqrt(tau0);
  const std::vector<double> y = WhiteNoise(1 << 18, sigma_w, 1);
  // WHEN its Allan deviation is computed
  const std::vector<std::size_t> m = OctaveClusterSizes(y.size());
  const std::vector<double> adev = OverlappingAllanDeviation(y, tau0, m);
  // THEN σ(τ) = N/√τ within the estimate's scatter (about 1/√(N/m))
  for (std::size_t i = 0; i < m.size() && m[i] <= 512; ++i) {
    const double tau = static_cast<double>(m[i]) * tau0;
    EXPECT_NEAR(adev[i] / (n_density / std::sqrt(tau)), 1.0, 0.06) << "m=" << m[i];
  }
}

TEST(AllanDeviationTest, RateRandomWalkFollowsKTimesRootTauOverThree) {
  // GIVEN a rate random walk of K: y_k = y_{k−1} + K·√τ0·w_k
  const double tau0 = 0.01, k_rw = 1e-3;
  std::vector<double> y = WhiteNoise(1 << 17, k_rw * std::sqrt(tau0), 2);
  for (std::size_t k = 1; k < y.size(); ++k) y[k] += y[k - 1];
  const std::vector<std::size_t> m = OctaveClusterSizes(y.size());
  const std::vector<double> adev = OverlappingAllanDeviation(y, tau0, m);
  // THEN σ(τ) = K·√(τ/3) once τ is many samples long (fewer independent clusters: wider scatter)
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m[i] < 8 || m[i] > 256) continue;
    const double tau = static_cast<double>(m[i]) * tau0;
    EXPECT_NEAR(adev[i] / (k_rw * std::sqrt(tau / 3)), 1.0, 0.15) << "m=" << m[i];
  }
}

TEST(AllanDeviationTest, AgreesWithTheDefinitionComputedDirectly) {
  // GIVEN white noise, a random walk, a large constant and a sine (a vibration)
  const double tau0 = 0.005;
  std::vector<double> y = WhiteNoise(20000, 0.05, 3), rw = WhiteNoise(20000, 1e-4, 4);
  double walk = 0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    walk += rw[k];
    y[k] +=
        9.81 + walk + 0.3 * std::sin(2 * 3.14159265358979 * 23.0 * static_cast<double>(k) * tau0);
  }
  const std::vector<std::size_t> m = OctaveClusterSizes(y.size());
  const std::vector<double> adev = OverlappingAllanDeviation(y, tau0, m);
  // THEN both algorithms agree far inside 2 % at every τ
  for (std::size_t i = 0; i < m.size(); ++i)
    EXPECT_NEAR(adev[i] / DirectAllanDeviation(y, m[i]), 1.0, 1e-9) << "m=" << m[i];
}

TEST(AllanDeviationTest, RejectsClustersLongerThanHalfTheSeries) {
  EXPECT_THROW(OverlappingAllanDeviation(std::vector<double>(10, 1.0), 1, {6}),
               std::invalid_argument);
  EXPECT_THROW(OverlappingAllanDeviation(std::vector<double>(10, 1.0), 1, {0}),
               std::invalid_argument);
}

// the real walk_0827 log's longest still period: hil characterize against the direct definition
TEST(AllanDeviationTest, RealLogStillPeriodAgreesWithTheDefinition) {
  const std::filesystem::path csv =
      std::filesystem::path(HIL_SHARED_DIR) / "vectors/real_imu/walk_0827/imu_1730.csv";
  if (!std::filesystem::exists(csv)) GTEST_SKIP() << csv << " absent";
  CharacterizeOptions o;
  o.still = true;
  const ImuSeries log = ReadImuLog(csv.string());
  const Characterization c = Characterize(log, o);
  const UniformImu u = ResampleUniform(log, c.step_s);
  const auto first = static_cast<std::size_t>(std::llround(c.from_s / c.step_s));
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> g, a;
    for (std::size_t i = first; i < first + c.samples; ++i) {
      g.push_back(u.gyro_radps[i][axis]);
      a.push_back(u.accel_mps2[i][axis]);
    }
    const auto ax = static_cast<std::size_t>(axis);
    for (std::size_t i = 0; i < c.tau_s.size(); ++i) {
      const auto m = static_cast<std::size_t>(std::llround(c.tau_s[i] / c.step_s));
      EXPECT_NEAR(c.adev_gyro_radps[ax][i] / DirectAllanDeviation(g, m), 1.0, 0.02);
      EXPECT_NEAR(c.adev_accel_mps2[ax][i] / DirectAllanDeviation(a, m), 1.0, 0.02);
    }
  }
}

}  // namespace
}  // namespace hil::harness

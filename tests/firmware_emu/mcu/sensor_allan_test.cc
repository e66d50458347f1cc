// Statistical tests of the sensor models: the Allan deviation of a long static record recovers
// the configured white-noise density and bias instability within 10 %.
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

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kDt = 0.1;  // 10 Hz: seed 000's IMU rate

// GIVEN a triad at rest WHEN it is sampled n times THEN the per-axis records of Measure()
std::vector<std::vector<double>> StaticRecord(const TriadSpec& spec, std::size_t n,
                                              std::uint64_t seed, bool quantised) {
  SensorTriad triad(spec, kDt, seed);
  std::vector<std::vector<double>> axes(3, std::vector<double>(n));
  for (std::size_t k = 0; k < n; ++k) {
    const Time t = TimeFromSeconds(static_cast<double>(k) * kDt);
    Eigen::Vector3d v;
    if (quantised) {
      const TriadCounts c = triad.Sample(Eigen::Vector3d::Zero(), t, 25.0);
      for (int i = 0; i < 3; ++i) v[i] = c.counts[i] * triad.output_lsb();
    } else {
      v = triad.Measure(Eigen::Vector3d::Zero(), t, 25.0);
    }
    for (int i = 0; i < 3; ++i) axes[static_cast<std::size_t>(i)][k] = v[i];
  }
  return axes;
}

TEST(SensorAllanTest, RazorGyroRecoversNoiseDensityAndBiasInstability) {
  // the Razor v13 gyro model (0.035 °/s/√Hz, B = 100 °/h); a shorter correlation time keeps the
  // record short while leaving thousands of clusters at the bias-instability peak
  TriadSpec spec = ProfileByName("razor-v13").gyro;
  spec.error.bias_correlation_time_s = 20;
  spec.error.turn_on_bias_sigma.setZero();
  spec.error.bias_temperature_coeff_per_c = 0;
  const auto axes = StaticRecord(spec, 500000, 42, false);
  for (const auto& y : axes) {
    const auto a = test::AllanDeviation(y, kDt);
    const double n_hat = test::NoiseDensityFromAllan(a);
    const double b_hat = test::BiasInstabilityFromAllan(a, n_hat);
    std::printf(
        "razor gyro: N = %.5f deg/s/rtHz (configured %.5f), B = %.2f deg/h (configured %.2f)\n",
        n_hat / kDeg, spec.error.noise_density[0] / kDeg, b_hat / kDeg * 3600,
        spec.error.bias_instability / kDeg * 3600);
    EXPECT_NEAR(n_hat / spec.error.noise_density[0], 1.0, 0.10)
        << "N = " << n_hat / kDeg << " °/s/√Hz";
    EXPECT_NEAR(b_hat / spec.error.bias_instability, 1.0, 0.10)
        << "B = " << b_hat / kDeg * 3600 << " °/h";
  }
}

TEST(SensorAllanTest, IndustrialAccelRecoversNoiseDensityAndBiasInstability) {
  TriadSpec spec = ProfileByName("industrial-mems").accel;
  spec.error.bias_correlation_time_s = 20;
  spec.error.bias_instability = 20e-6 * 9.80665;  // well above the white floor at the peak
  const auto axes = StaticRecord(spec, 500000, 7, false);
  for (const auto& y : axes) {
    const auto a = test::AllanDeviation(y, kDt);
    const double n_hat = test::NoiseDensityFromAllan(a);
    std::printf(
        "industrial accel: N = %.4g m/s^2/rtHz (configured %.4g), B = %.4g m/s^2 (configured "
        "%.4g)\n",
        n_hat, spec.error.noise_density[0], test::BiasInstabilityFromAllan(a, n_hat),
        spec.error.bias_instability);
    EXPECT_NEAR(n_hat / spec.error.noise_density[0], 1.0, 0.10);
    EXPECT_NEAR(test::BiasInstabilityFromAllan(a, n_hat) / spec.error.bias_instability, 1.0, 0.10);
  }
}

TEST(SensorAllanTest, PointSamplingAliasesNoiseAboveNyquist) {
  // the ADXL345 read at the sample instant: white noise band-limited to 50 Hz, sampled at 10 Hz,
  // looks like a density of N·√(π·BW / (2·fs)) ≈ 2.8 N
  TriadSpec spec = ProfileByName("razor-v13").accel;
  spec.error.bias_instability = 0;
  spec.error.turn_on_bias_sigma.setZero();
  const auto axes = StaticRecord(spec, 100000, 3, false);
  const double factor = std::sqrt(std::numbers::pi * spec.error.bandwidth_hz * kDt / 2.0);
  for (int i = 0; i < 3; ++i) {
    const auto a = test::AllanDeviation(axes[static_cast<std::size_t>(i)], kDt);
    EXPECT_NEAR(test::NoiseDensityFromAllan(a) / (spec.error.noise_density[i] * factor), 1.0, 0.05);
  }
}

TEST(SensorAllanTest, RazorAdcQuantisationAddsItsKnownWhiteTerm) {
  // 16 conversions, each with 0.5-count transition noise and a rounding error of variance 1/12
  // count², summed: σ = √(16·(0.25 + 1/12)) ≈ 2.31 output LSB per sample, in quadrature with the
  // gyro's own white noise
  TriadSpec spec = ProfileByName("razor-v13").gyro;
  spec.error.bias_instability = 0;
  spec.error.turn_on_bias_sigma.setZero();
  const auto axes = StaticRecord(spec, 100000, 5, true);
  const double lsb = spec.counts.output_lsb();
  const double adc_sigma = std::sqrt(16.0 * (0.25 + 1.0 / 12.0)) * lsb;
  const double expected = std::hypot(spec.error.noise_density[0], adc_sigma * std::sqrt(kDt));
  for (const auto& y : axes) {
    const auto a = test::AllanDeviation(y, kDt);
    EXPECT_NEAR(test::NoiseDensityFromAllan(a) / expected, 1.0, 0.10);
  }
}

}  // namespace
}  // namespace hil::mcu

// navd's UWB-mode planar filter: on a simulated drive (0.5 m/s, a gentle turn, 5 Hz UWB with
// 0.06 m white noise, a 10 Hz yaw gyro with a 0.5 °/s bias, the sensor's heading) it beats the raw
// fixes, learns the bias and the speed, rejects an NLOS jump and restarts after a lasting one.
#include "hil/estimator/uwb/uwb_planar_filter.h"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

namespace hil::estimator::uwb {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(UwbPlanarFilterTest, BeatsRawFixesAndLearnsBiasAndSpeed) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n01(0, 1);
  UwbPlanarFilter f;
  Eigen::Vector2d p(-7, -7);
  double psi = 90 * kDeg;
  const double v = 0.5, rate = 2 * kDeg, bias = 0.5 * kDeg, dt = 0.2;
  f.Initialize(p + 0.06 * Eigen::Vector2d(n01(rng), n01(rng)), psi);
  double raw2 = 0, est2 = 0, speed_sum = 0;
  int n = 0;
  for (int k = 0; k < 600; ++k) {  // 120 s
    for (int j = 0; j < 20; ++j) {
      p += v * dt / 20 * Eigen::Vector2d(std::cos(psi), std::sin(psi));
      psi += rate * dt / 20;
    }
    f.Predict(rate + bias, dt);
    f.UpdateYaw(psi + 0.01 * n01(rng));
    const Eigen::Vector2d z = p + 0.06 * Eigen::Vector2d(n01(rng), n01(rng));
    EXPECT_TRUE(f.UpdatePosition(z));
    if (k < 100) continue;
    raw2 += (z - p).squaredNorm();
    est2 += (f.position() - p).squaredNorm();
    speed_sum += f.speed_mps();
    ++n;
  }
  const double raw = std::sqrt(raw2 / n), est = std::sqrt(est2 / n);
  EXPECT_LT(est, 0.6 * raw) << raw << " " << est;
  EXPECT_NEAR(speed_sum / n, v, 0.02);
  EXPECT_NEAR(f.speed_mps(), v, 0.1);
  EXPECT_NEAR(f.rate_bias_radps(), bias, 0.2 * kDeg);
  EXPECT_EQ(f.stats().position_rejected, 0u);
}

TEST(UwbPlanarFilterTest, GatesAnNlosJumpAndRestartsAfterALastingOne) {
  UwbPlanarFilterParams params;
  params.reset_after_rejections = 3;
  UwbPlanarFilter f(params);
  f.Initialize({0, 0}, 0);
  for (int k = 0; k < 20; ++k) {
    f.Predict(0, 0.2);
    f.UpdatePosition({0, 0});
  }
  f.Predict(0, 0.2);
  EXPECT_FALSE(f.UpdatePosition({1.0, 0}));  // a 1 m jump: ~16σ
  EXPECT_LT(f.position().norm(), 0.01);
  EXPECT_FALSE(f.UpdatePosition({1.0, 0}));
  EXPECT_FALSE(f.UpdatePosition({1.0, 0}));  // third in a row: restart there
  EXPECT_EQ(f.stats().resets, 1u);
  EXPECT_NEAR(f.position().x(), 1.0, 1e-12);
  EXPECT_TRUE(std::isfinite(f.position_std_m().x()));
}

}  // namespace
}  // namespace hil::estimator::uwb

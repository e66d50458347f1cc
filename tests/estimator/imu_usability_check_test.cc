// ImuUsabilityCheck: the accelerometer's mean specific force against the GNSS velocities'. A
// usable IMU (its bias constant, noise as modelled, vibration zero-mean) never trips it; an
// apparent bias that wanders far beyond its random walk (an engine order aliased near DC) does,
// and the IMU is usable again once the wander stops.
#include "hil/estimator/imu_usability_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
const Eigen::Vector3d kG_N(0, 0, -9.80);

// A level vehicle driving east, its speed 1 + 0.3 sin(2π t / 40 s) (m/s), the IMU at 100 Hz, GNSS
// velocity at 1 Hz (σ 0.1 m/s horizontal, 0.2 vertical). `bias(t)` is the accelerometer's offset.
struct Drive {
  template <typename Bias, typename Vibration>
  void Run(ImuUsabilityCheck& check, double t_end_s, Bias bias, Vibration vibration) {
    const double dt = 0.01;
    for (; t_s < t_end_s - 1e-9; ++k) {
      const double tm = t_s + 0.5 * dt;
      const double a = 0.3 * 2 * M_PI / 40 * std::cos(2 * M_PI * tm / 40);
      const Eigen::Vector3d f_B = Eigen::Vector3d(a, 0, 9.80) + bias(tm) + vibration(tm);
      Eigen::Vector3d dv;
      for (int i = 0; i < 3; ++i) dv[i] = f_B[i] * dt + 0.0125 * std::sqrt(dt) * n01(rng);
      check.AddImu(Eigen::Vector3d::Zero(), dv, dt);
      t_s += dt;
      if ((k + 1) % 100 == 0) {
        const double v = 1 + 0.3 * std::sin(2 * M_PI * t_s / 40);
        const Eigen::Vector3d std(0.1, 0.1, 0.2);
        const Eigen::Vector3d vel(v + 0.1 * n01(rng), 0.1 * n01(rng), 0.2 * n01(rng));
        const bool tested =
            check.AddGnssVelocity(kT0 + Nanoseconds{std::llround(t_s * 1e9)}, vel, std, kG_N);
        if (tested) {
          ++tests;
          unusable_tests += check.unusable();
          max_stat = std::max(max_stat, check.statistic());
          if (check.unusable() && first_unusable_s < 0) first_unusable_s = t_s;
          if (!check.unusable() && first_unusable_s >= 0 && usable_again_s < 0)
            usable_again_s = t_s;
        }
      }
    }
  }
  double t_s = 0;
  long k = 0;
  int tests = 0, unusable_tests = 0;
  double max_stat = 0, first_unusable_s = -1, usable_again_s = -1;
  std::mt19937 rng{7};
  std::normal_distribution<double> n01{0.0, 1.0};
};

ImuUsabilityCheck Check() { return ImuUsabilityCheck({}, 0.0125, 5e-4); }

TEST(ImuUsabilityCheckTest, ConsistentImuIsUsable) {
  ImuUsabilityCheck check = Check();
  Drive d;
  // a turn-on bias of 0.5 m/s² (constant) and white noise as modelled, one hour
  d.Run(
      check, 3600, [](double) { return Eigen::Vector3d(0.3, -0.2, 0.5); },
      [](double) { return Eigen::Vector3d::Zero(); });
  std::printf("consistent: %d tests, max statistic %.1f (threshold %.1f)\n", d.tests, d.max_stat,
              check.enter_threshold());
  EXPECT_GT(d.tests, 300);
  EXPECT_EQ(d.unusable_tests, 0) << "max statistic " << d.max_stat;
  EXPECT_EQ(check.unusable_periods(), 0u);
  EXPECT_LT(d.max_stat, check.enter_threshold());
}

TEST(ImuUsabilityCheckTest, ZeroMeanVibrationIsNotABias) {
  ImuUsabilityCheck check = Check();
  Drive d;
  // 2.5 m/s² at 33 Hz and 1.5 m/s² at 3.1 Hz on every axis: large, but zero-mean
  d.Run(
      check, 1800, [](double) { return Eigen::Vector3d(0.1, 0.1, 0.1); },
      [](double t) {
        const double s = 2.5 * std::sin(2 * M_PI * 33.3 * t) + 1.5 * std::sin(2 * M_PI * 3.1 * t);
        return Eigen::Vector3d(s, -s, s);
      });
  EXPECT_EQ(check.unusable_periods(), 0u) << "max statistic " << d.max_stat;
}

TEST(ImuUsabilityCheckTest, WanderingBiasMakesItUnusableUntilItStops) {
  ImuUsabilityCheck check = Check();
  Drive d;
  // the two-stroke's aliased order 1: 2.3 m/s² (z) and 1.15 m/s² (x) times sin of a phase turning
  // with a 250 s period (field_realism/README), for 600 s; then constant
  const auto wander = [](double t) {
    const double s = std::sin(2 * M_PI * std::min(t, 600.0) / 250);
    return Eigen::Vector3d(1.15 * s, 0.77 * s, 2.3 * s);
  };
  d.Run(check, 600, wander, [](double) { return Eigen::Vector3d::Zero(); });
  EXPECT_GE(d.first_unusable_s, 0);
  EXPECT_LT(d.first_unusable_s, 120);
  EXPECT_GT(check.statistic(), 0);
  // most tests of the wandering period find it unusable
  EXPECT_GT(d.unusable_tests, d.tests * 3 / 4);
  // once the offset holds still, the IMU is consistent again within a few tests
  d.Run(check, 900, wander, [](double) { return Eigen::Vector3d::Zero(); });
  std::printf("wandering: unusable from %.0f s, %d of %d tests; usable again at %.0f s\n",
              d.first_unusable_s, d.unusable_tests, d.tests, d.usable_again_s);
  EXPECT_FALSE(check.unusable());
  EXPECT_GT(d.usable_again_s, 600);
  EXPECT_LT(d.usable_again_s, 800);
}

TEST(ImuUsabilityCheckTest, ThresholdsAreTheChiSquareQuantiles) {
  const ImuUsabilityCheck check = Check();
  // χ²(11): upper 1e-6 quantile 48.87, 95 % 19.68 (the closed form of the odd-dof survival
  // function); Wilson–Hilferty within 3 % so far in the tail, on the safe side
  EXPECT_EQ(check.dof(), 11);
  EXPECT_GE(check.enter_threshold(), 48.87);
  EXPECT_LT(check.enter_threshold(), 48.87 * 1.03);
  EXPECT_NEAR(check.leave_threshold(), 19.68, 0.2);
}

}  // namespace
}  // namespace hil::estimator

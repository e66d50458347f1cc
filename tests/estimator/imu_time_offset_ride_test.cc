// The IMU tag lag estimate (imu_time_offset.h) on a tractor whose ride shakes the IMU about its
// heading: 1 m/s on 60 s rows with 12 s headland turns, the antenna 1.2 m ahead of the IMU (paper
// 004's rig), the gyro's heading carrying a ride of 0.3 °/s r.m.s. in 1-15 Hz plus 0.3 °/s in the
// 1.2-2.5 Hz roll band (imu_error_model.md, industrial_mems_tractor), as a sum of sinusoids of
// seeded frequencies and phases. The GNSS courses are the vehicle's (the ride is the sensor's).
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/imu_time_offset.h"

namespace hil::estimator {
namespace {

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
constexpr double kSpeedMps = 1.0;
constexpr double kLeverXm = 1.2;
constexpr double kDeg = std::numbers::pi / 180.0;

// 60 s straight, then a 180° turn in 12 s (1 s ramps), alternating left and right
double YawRateRadps(double t_s) {
  const double period_s = 72.0;
  const double u = std::fmod(t_s, period_s);
  const double sign = static_cast<long>(t_s / period_s) % 2 == 0 ? 1.0 : -1.0;
  const double w_max = std::numbers::pi / 11.0;  // 12 s with 1 s ramps turn 180°
  if (u < 60.0) return 0.0;
  if (u < 61.0) return sign * w_max * (u - 60.0);
  if (u < 71.0) return sign * w_max;
  return sign * w_max * (72.0 - u);
}

// the ride's heading (rad): sinusoids whose rate amplitudes give the bands' r.m.s.
class RideHeading {
 public:
  explicit RideHeading(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    AddBand(rng, u01, 1.0, 15.0, 0.3 * kDeg);
    AddBand(rng, u01, 1.2, 2.5, 0.3 * kDeg);
  }
  double At(double t_s) const {
    double a = 0.0;
    for (const Component& c : components_)
      a += c.rate_amplitude_radps / (2.0 * std::numbers::pi * c.f_hz) *
           std::sin(2.0 * std::numbers::pi * c.f_hz * t_s + c.phase_rad);
    return a;
  }

 private:
  struct Component {
    double f_hz, rate_amplitude_radps, phase_rad;
  };
  void AddBand(std::mt19937& rng, std::uniform_real_distribution<double>& u01, double lo_hz,
               double hi_hz, double rate_rms_radps) {
    constexpr int kPerBand = 40;
    const double amplitude = rate_rms_radps * std::sqrt(2.0 / kPerBand);
    for (int i = 0; i < kPerBand; ++i)
      components_.push_back(
          {lo_hz + (hi_hz - lo_hz) * u01(rng), amplitude, 2.0 * std::numbers::pi * u01(rng)});
  }
  std::vector<Component> components_;
};

// the IMU's samples at 100 Hz tagged lag_s late, the fixes' courses at 10 Hz
ImuTimeOffset Drive(double lag_s, double duration_s, unsigned seed) {
  ImuTimeOffset est;
  est.SetLeverArm(kLeverXm, 0.0);
  const RideHeading ride(seed);
  std::mt19937 rng(seed + 1);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double vel_std_mps = 0.01;  // an RTK receiver's velocity
  const double dt_s = 0.001;        // the truth's integration step
  double psi = 0.3, last_imu_psi = psi + ride.At(0.0);
  for (int k = 1; k * dt_s <= duration_s + 1e-9; ++k) {
    const double t = k * dt_s;
    psi += YawRateRadps(t - 0.5 * dt_s) * dt_s;
    if (k % 10 == 0) {  // sensed at t, tagged lag_s later
      const double imu_psi = psi + ride.At(t);
      est.AddImu(kT0 + Nanoseconds{std::llround((t + lag_s) * 1e9)}, imu_psi - last_imu_psi);
      last_imu_psi = imu_psi;
    }
    if (k % 100 == 0) {  // the antenna's velocity, ahead of the IMU by the lever arm
      const double w = YawRateRadps(t);
      const double chi = psi + std::atan2(w * kLeverXm, kSpeedMps);
      const double v = std::hypot(kSpeedMps, w * kLeverXm);
      est.AddVelocity(kT0 + Nanoseconds{std::llround(t * 1e9)},
                      v * std::cos(chi) + vel_std_mps * n01(rng),
                      v * std::sin(chi) + vel_std_mps * n01(rng), vel_std_mps);
    }
  }
  return est;
}

// before the heading's mean over heading_window_s, the ride's shaking (times 2π f l_x / v through
// the lever arm's course) made a lag-free IMU conclusively late: 0.21-0.29 s on the tractor
TEST(ImuTimeOffsetRideTest, TheRideIsNoLag) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const ImuTimeOffset est = Drive(0.0, 600.0, seed);
    EXPECT_FALSE(est.lag_s().has_value())
        << "seed " << seed << ": lag " << est.best_lag_s() << " σ " << est.lag_std_s()
        << " evidence " << est.evidence();
  }
}

// the mean keeps the turns' heading ramps: a real lag is still found through the ride
TEST(ImuTimeOffsetRideTest, FindsARealLagThroughTheRide) {
  const ImuTimeOffset est = Drive(0.1, 600.0, 1u);
  ASSERT_TRUE(est.lag_s().has_value())
      << "best " << est.best_lag_s() << " σ " << est.lag_std_s() << " evidence " << est.evidence();
  EXPECT_NEAR(*est.lag_s(), 0.1, 0.01);
}

}  // namespace
}  // namespace hil::estimator

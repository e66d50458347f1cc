// The vibration front end (issue 41): an engine order appears at order × RPM/60, aliases to
// |f − k·f_out| after decimation when the anti-alias low-pass is wider than half the output rate
// (and is attenuated when it is not), ride vibration has the PSD asked for, the mount resonance
// amplifies by 1/(2ζ), clipping holds the range, the same seed gives the same samples, the
// vibration's rotation tilts gravity into the accelerometer, and the ride scales with the ground
// speed.
#include "hil/firmware_emu/mcu/imu_front_end.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/mcu/biquad3.h"

namespace hil::mcu {
namespace {

constexpr double kPi = std::numbers::pi;

// Amplitude of the sinusoid at f_hz in a record sampled at fs_hz (single-bin DFT over a whole
// number of periods of the record).
double ToneAmplitude(const std::vector<double>& x, double fs_hz, double f_hz) {
  double re = 0, im = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double a = 2 * kPi * f_hz * static_cast<double>(k) / fs_hz;
    re += x[k] * std::cos(a);
    im += x[k] * std::sin(a);
  }
  return 2.0 * std::hypot(re, im) / static_cast<double>(x.size());
}

RoughImuSpec OneOrder(double order, double rpm, double amp_z_mps2, double internal_hz) {
  RoughImuSpec s;
  s.internal_rate_hz = internal_hz;
  s.rpm_profile = {{0, rpm}};
  EngineOrder o;
  o.order = order;
  o.accel_amplitude_mps2 = Eigen::Vector3d(0, 0, amp_z_mps2);
  o.gyro_amplitude_radps = Eigen::Vector3d(0.01, 0, 0);
  s.engine_orders = {o};
  return s;
}

// Specific force on `axis` (less 1 g on z) of `n` output samples at `out_hz` of a level board
// with vibration, the vehicle at speed_mps(k) (the ride's speed; nullptr: never set).
std::vector<double> RecordZ(const RoughImuSpec& s, const FrontEndLimits& l, double out_hz,
                            std::size_t n, std::uint64_t seed, std::size_t axis = 2,
                            const std::function<double(std::size_t)>& speed_mps = nullptr) {
  ImuFrontEnd fe(s, l, seed);
  std::vector<double> z;
  const Eigen::Vector3d g(0, 0, 9.80665);
  for (std::size_t k = 0; k < n; ++k) {
    Eigen::Vector3d f, w;
    if (speed_mps) fe.SetGroundSpeed(speed_mps(k));
    fe.Advance(TimeFromSeconds(static_cast<double>(k) / out_hz), g, Eigen::Vector3d::Zero(), f, w);
    z.push_back(f[static_cast<Eigen::Index>(axis)] - (axis == 2 ? 9.80665 : 0.0));
  }
  return z;
}

FrontEndLimits Wide(double aaf_hz) {
  FrontEndLimits l;
  l.accel_range_mps2 = 16 * 9.80665;
  l.gyro_range_radps = 10;
  l.accel_aaf_hz = aaf_hz;
  l.gyro_aaf_hz = aaf_hz;
  return l;
}

TEST(ImuFrontEndTest, AnEngineOrderAppearsAtOrderTimesRpmOver60) {
  // four-stroke four-cylinder firing order 2 at 1800 RPM: 60 Hz; output 1 kHz (no aliasing)
  const RoughImuSpec s = OneOrder(2, 1800, 1.0, 4000);
  const FrontEndLimits l = Wide(400);
  const auto z = RecordZ(s, l, 1000, 4000, 7);
  const double gain = Biquad3::ButterworthLowPass(400, 4000).Gain(60, 4000);
  EXPECT_NEAR(ToneAmplitude(z, 1000, 60), gain, 0.01);
  EXPECT_LT(ToneAmplitude(z, 1000, 30), 0.01);
  EXPECT_LT(ToneAmplitude(z, 1000, 90), 0.01);
}

TEST(ImuFrontEndTest, AToneAboveHalfTheOutputRateAliasesThroughAWideFilter) {
  // 130 Hz (order 1 at 7800 RPM, a small two-stroke) sampled at 100 Hz aliases to 30 Hz
  const RoughImuSpec s = OneOrder(1, 7800, 2.0, 2000);
  const auto wide = RecordZ(s, Wide(400), 100, 2000, 3);
  const double g_wide = Biquad3::ButterworthLowPass(400, 2000).Gain(130, 2000);
  EXPECT_NEAR(ToneAmplitude(wide, 100, 30), 2.0 * g_wide, 0.03);
  EXPECT_LT(ToneAmplitude(wide, 100, 20), 0.02);
  // a cutoff below half the output rate attenuates it as its response at 130 Hz says
  const auto narrow = RecordZ(s, Wide(20), 100, 2000, 3);
  const double g_narrow = Biquad3::ButterworthLowPass(20, 2000).Gain(130, 2000);
  EXPECT_LT(g_narrow, 0.03);
  EXPECT_NEAR(ToneAmplitude(narrow, 100, 30), 2.0 * g_narrow, 0.01);
}

TEST(ImuFrontEndTest, RideVibrationHasThePsdAsked) {
  RoughImuSpec s;
  s.internal_rate_hz = 1000;
  RideBand b;
  b.f_low_hz = 2;
  b.f_high_hz = 40;
  b.accel_psd_mps2_sq_per_hz = Eigen::Vector3d(0, 0, 0.01);  // 0.62 m/s² r.m.s. over the band
  s.ride = {b};
  const auto z = RecordZ(s, Wide(450), 1000, 200000, 11);
  double ss = 0;
  for (double v : z) ss += v * v;
  const double rms = std::sqrt(ss / static_cast<double>(z.size()));
  // a flat PSD S between Butterworth skirts: variance S·(f_high − f_low) up to the skirts' share
  // (a second-order Butterworth's noise bandwidth is π/(2√2) ≈ 1.11 × its cutoff)
  const double expected = std::sqrt(0.01 * (40 - 2) * 1.1107);
  EXPECT_NEAR(rms / expected, 1.0, 0.08) << "rms " << rms << " expected " << expected;
  // in-band density: mean power of 10–20 Hz bins ≈ S
  double p = 0;
  for (int f = 10; f <= 20; ++f) {
    const double a = ToneAmplitude(z, 1000, f);
    p += a * a / 2.0;
  }
  const double bin_hz = 1000.0 / static_cast<double>(z.size());
  EXPECT_NEAR(p / 11.0 / bin_hz / 0.01, 1.0, 0.6);  // a single periodogram bin scatters by ~100 %
}

// z specific force less 1 g of `n` samples at 1 kHz output, the vehicle at speed_mps(k).
std::vector<double> RecordZAtSpeed(const RoughImuSpec& s, std::size_t n,
                                   const std::function<double(std::size_t)>& speed_mps) {
  return RecordZ(s, Wide(450), 1000, n, 5, 2, speed_mps);
}

double SumOfSquares(const std::vector<double>& x, std::size_t from = 0) {
  double ss = 0;
  for (std::size_t k = from; k < x.size(); ++k) ss += x[k] * x[k];
  return ss;
}

// The ride comes from the ground (ISO 8608 terrain: acceleration PSD ∝ speed): twice the
// reference speed doubles its power, a standing vehicle has none, and a vehicle that stops
// rings down to nothing. Without a reference speed the ride ignores the speed.
TEST(ImuFrontEndTest, TheRideGrowsWithTheGroundSpeedAndStopsWithTheVehicle) {
  RoughImuSpec s;
  s.internal_rate_hz = 1000;
  RideBand b;
  b.f_low_hz = 2;
  b.f_high_hz = 40;
  b.accel_psd_mps2_sq_per_hz = Eigen::Vector3d(0, 0, 0.01);
  s.ride = {b};
  s.ride_reference_speed_mps = 1.0;
  const std::size_t n = 20000;
  const auto at_ref = RecordZAtSpeed(s, n, [](std::size_t) { return 1.0; });
  const auto at_twice = RecordZAtSpeed(s, n, [](std::size_t) { return 2.0; });
  const auto reversing = RecordZAtSpeed(s, n, [](std::size_t) { return -1.0; });
  const auto standing = RecordZAtSpeed(s, n, [](std::size_t) { return 0.0; });
  const auto stopping = RecordZAtSpeed(s, n, [](std::size_t k) { return k < 5000 ? 1.0 : 0.0; });
  ASSERT_GT(SumOfSquares(at_ref), 100.0);  // 0.62 m/s² r.m.s. over 20 000 samples
  EXPECT_NEAR(SumOfSquares(at_twice) / SumOfSquares(at_ref), 2.0, 1e-9);
  EXPECT_EQ(reversing, at_ref);
  EXPECT_EQ(SumOfSquares(standing), 0.0);
  EXPECT_GT(SumOfSquares(stopping), 1.0);
  EXPECT_LT(SumOfSquares(stopping, 7000), 1e-6);  // 2 s after the stop: rung down
  s.ride_reference_speed_mps = 0;
  EXPECT_EQ(RecordZAtSpeed(s, n, [](std::size_t) { return 0.0; }), at_ref);
}

// A roll oscillation of the board (a ride band on the x gyro only, no translation) tilts gravity
// into the accelerometer as a rigid board would: the y axis reads g·θ_x, with θ_x the angle the
// x gyro's output integrates to (f_S = f − θ × f); before, the accelerometer read 0 throughout.
TEST(ImuFrontEndTest, ARollOscillationTiltsGravityIntoTheAccelerometer) {
  RoughImuSpec s;
  s.internal_rate_hz = 1000;
  RideBand b;
  b.f_low_hz = 1.2;
  b.f_high_hz = 2.5;
  b.gyro_psd_radps_sq_per_hz = Eigen::Vector3d(2e-4, 0, 0);  // about 1° /s r.m.s. over the band
  s.ride = {b};
  ImuFrontEnd fe(s, Wide(300), 5);
  const double g = 9.80665;
  const double out_hz = 100;
  double theta_x = 0, sum_sq_fy = 0, sum_sq_err = 0;
  for (int k = 0; k < 60000; ++k) {  // 600 s
    Eigen::Vector3d f, w;
    fe.Advance(TimeFromSeconds(k / out_hz), Eigen::Vector3d(0, 0, g), Eigen::Vector3d::Zero(), f,
               w);
    theta_x += w.x() / out_hz;
    if (k < 2000) continue;  // the angle's start-up
    sum_sq_fy += f.y() * f.y();
    sum_sq_err += (f.y() - g * theta_x) * (f.y() - g * theta_x);
  }
  const double rms_fy = std::sqrt(sum_sq_fy / 58000.0);
  const double rms_err = std::sqrt(sum_sq_err / 58000.0);
  // the roll band's angle: 1°/s r.m.s. at about 1.7 Hz is about 0.1° = 1.6 mrad: 0.016 m/s²
  EXPECT_GT(rms_fy, 0.005);
  // the y reading is the tilted gravity, up to the rectangle rule of the test's own integral and
  // the 10 s leak of the emulator's angle (a few per cent of the band's angle)
  EXPECT_LT(rms_err, 0.15 * rms_fy) << "y r.m.s. " << rms_fy << ", off g·θ by " << rms_err;
}

TEST(ImuFrontEndTest, TheMountResonanceAmplifiesByOneOverTwoZeta) {
  const Biquad3 m = Biquad3::MountTransmissibility(80, 0.1, 2000);
  EXPECT_NEAR(m.Gain(80, 2000), std::sqrt(1 + 1 / (4 * 0.01)), 0.05);  // √(1+(1/2ζ)²) at fn
  EXPECT_NEAR(m.Gain(1, 2000), 1.0, 0.01);
  EXPECT_LT(m.Gain(400, 2000), 0.2);
  RoughImuSpec s = OneOrder(1, 4800, 1.0, 2000);  // 80 Hz
  s.mount = {80, 0.1};
  const auto z = RecordZ(s, Wide(900), 2000, 8000, 5);
  const double aaf = Biquad3::ButterworthLowPass(900, 2000).Gain(80, 2000);
  EXPECT_NEAR(ToneAmplitude(z, 2000, 80), m.Gain(80, 2000) * aaf, 0.1);
}

TEST(ImuFrontEndTest, ClippingHoldsTheRangeAndRectifies) {
  // 2 g peak at 60 Hz on top of 1 g against a ±2 g range: the tops are cut, the mean drops
  const RoughImuSpec s = OneOrder(2, 1800, 2 * 9.80665, 4000);
  FrontEndLimits l = Wide(400);
  l.accel_range_mps2 = 2 * 9.80665;
  const auto z = RecordZ(s, l, 1000, 4000, 9);
  double mean = 0, top = -1e9;
  for (double v : z) mean += v / static_cast<double>(z.size()), top = std::max(top, v);
  EXPECT_LT(top, 9.80665 * 1.1);  // output at most the range (+ the filter's overshoot)
  EXPECT_LT(mean, -0.5);          // vibration rectified into a bias
}

TEST(ImuFrontEndTest, SameSeedSameSamplesOtherSeedOther) {
  RoughImuSpec s = OneOrder(2, 2000, 1.0, 1000);
  RideBand b;
  b.accel_psd_mps2_sq_per_hz = Eigen::Vector3d::Constant(0.01);
  s.ride = {b};
  const auto a = RecordZ(s, Wide(300), 100, 500, 21);
  const auto a2 = RecordZ(s, Wide(300), 100, 500, 21);
  const auto c = RecordZ(s, Wide(300), 100, 500, 22);
  EXPECT_EQ(a, a2);
  EXPECT_NE(a, c);
}

TEST(ImuFrontEndTest, RejectsACutoffAtOrAboveHalfTheInternalRate) {
  EXPECT_THROW(ImuFrontEnd(OneOrder(1, 1000, 1, 1000), Wide(500), 1), std::invalid_argument);
}

}  // namespace
}  // namespace hil::mcu

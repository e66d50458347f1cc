// The deterministic parts of the sensor models: quantisation, saturation, the ADC path,
// scale factor and misalignment, lever-arm kinematics, profile scales.
#include "hil/firmware_emu/mcu/sensor_triad.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "hil/firmware_emu/mcu/imu_kinematics.h"

namespace hil::mcu {
namespace {

constexpr double kG = 9.80665;
constexpr double kDeg = std::numbers::pi / 180.0;

TriadSpec Noiseless(TriadSpec s) {
  s.error = TriadErrorSpec{};
  s.counts.conversion_noise_counts = 0;
  return s;
}

TEST(SensorTriadTest, Adxl345FullResolutionCountsAndSaturation) {
  SensorTriad t(Noiseless(ProfileByName("razor-v13").accel), 0.1, 1);
  const TriadCounts one_g = t.Sample({0, 0, kG}, Time{}, 25);
  EXPECT_EQ(one_g.counts[2], 256);
  EXPECT_FALSE(one_g.saturated[2]);
  const TriadCounts big = t.Sample({3 * kG, -3 * kG, 0}, TimeFromSeconds(0.1), 25);
  EXPECT_EQ(big.counts[0], 511);  // ±2 g range, 10-bit register
  EXPECT_EQ(big.counts[1], -512);
  EXPECT_TRUE(big.saturated[0] && big.saturated[1]);
  EXPECT_FALSE(big.saturated[2]);
}

TEST(SensorTriadTest, RazorGyroAdcSumsSixteenConversionsAroundTheNominalZero) {
  const TriadSpec spec = Noiseless(ProfileByName("razor-v13").gyro);
  SensorTriad t(spec, 0.1, 1);
  // zero rate without ADC noise: the real zero-rate level (381.67 counts) rounds to the nominal 382
  EXPECT_EQ(t.Sample({0, 0, 0}, Time{}, 25).counts[0], 0);
  // 100 °/s = 103.3 counts above zero-rate → round(484.99) − 382 = 103 per conversion
  const double counts = 100 * kDeg / spec.counts.count_lsb;
  EXPECT_EQ(t.Sample({100 * kDeg, 0, 0}, TimeFromSeconds(0.1), 25).counts[0],
            16 * (std::lround(spec.counts.zero_count + counts) - 382));
  // the sensor saturates at ±300 °/s
  const TriadCounts sat = t.Sample({0, 500 * kDeg, 0}, TimeFromSeconds(0.2), 25);
  EXPECT_TRUE(sat.saturated[1]);
  EXPECT_NEAR(sat.counts[1] * spec.counts.output_lsb(), 300 * kDeg, 1.0 * kDeg);
}

TEST(SensorTriadTest, AdcTransitionNoiseDithersTheSubCountZeroOffset) {
  TriadSpec spec = Noiseless(ProfileByName("razor-v13").gyro);
  spec.counts.conversion_noise_counts = 0.5;
  SensorTriad t(spec, 0.1, 2);
  double sum = 0;
  const int n = 4000;
  for (int k = 0; k < n; ++k) sum += t.Sample({0, 0, 0}, TimeFromSeconds(0.1 * k), 25).counts[0];
  // 16 × (381.67 − 382) = −5.3 output LSB on average
  EXPECT_NEAR(sum / n, 16 * (spec.counts.zero_count - 382), 0.2);
}

TEST(SensorTriadTest, CompassOverflowReadsMinus4096) {
  SensorTriad t(Noiseless(ProfileByName("razor-v13").mag), 0.1, 1);
  const TriadCounts c = t.Sample({40, 0, -200}, Time{}, 25);
  EXPECT_EQ(c.counts[0], 520);
  EXPECT_EQ(c.counts[2], -4096);
  EXPECT_TRUE(c.saturated[2]);
}

TEST(SensorTriadTest, ScaleFactorAndMisalignmentApplyAsOneMatrix) {
  TriadSpec s;
  s.error.scale_factor_sigma_ppm = 10000;
  s.error.misalignment_sigma_rad = 0.01;
  SensorTriad a(s, 0.01, 3), b(s, 0.01, 3), c(s, 0.01, 4);
  const Eigen::Matrix3d& m = a.scale_misalignment();
  EXPECT_TRUE(m.isApprox(b.scale_misalignment()));
  EXPECT_FALSE(m.isApprox(c.scale_misalignment()));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m(i, i), 1.0, 0.05);
  const Eigen::Vector3d x(1, 2, 3);
  EXPECT_TRUE(a.Measure(x, Time{}, 25).isApprox(m * x, 1e-12));
}

TEST(SensorTriadTest, TemperatureDriftMovesTheBias) {
  TriadSpec s;
  s.error.bias_temperature_coeff_per_c = 0.01;
  SensorTriad t(s, 0.01, 1);
  EXPECT_NEAR(t.Measure({0, 0, 0}, Time{}, 35)[0], 0.1, 1e-12);
}

TEST(SensorTriadTest, AveragedVibrationIsTheMeanOverThePeriod) {
  TriadSpec s;
  s.sampling = Sampling::kAverage;
  SensorTriad t(s, 0.1, 1);
  // a 10 Hz tone averaged over exactly one period of 0.1 s vanishes
  t.SetVibration({{10.0, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d::Zero()}}, true);
  EXPECT_LT(t.Measure({0, 0, 0}, TimeFromSeconds(0.37), 25).norm(), 1e-12);
  TriadSpec p;
  p.sampling = Sampling::kPoint;
  SensorTriad u(p, 0.1, 1);
  u.SetVibration({{10.0, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d::Zero()}}, true);
  double peak = 0;
  for (int k = 0; k < 50; ++k)
    peak = std::max(peak, std::abs(u.Measure({0, 0, 0}, TimeFromSeconds(0.0137 * k), 25)[0]));
  EXPECT_GT(peak, 0.9);
}

TEST(ImuKinematicsTest, LeverArmAddsCentripetalAndTangentialTerms) {
  const Eigen::Vector3d f = SpecificForceAtLeverArm({0, 0, kG}, {0, 0, 1}, {0, 0, 2}, {1, 0, 0});
  EXPECT_NEAR(f.x(), -1.0, 1e-12);  // ω × (ω × r)
  EXPECT_NEAR(f.y(), 2.0, 1e-12);   // α × r
  EXPECT_NEAR(f.z(), kG, 1e-12);
}

TEST(ImuKinematicsTest, MountingRotationAndCompassIron) {
  TruthSample x;
  x.f_B_mps2 = {1, 0, kG};
  x.w_IB_B_radps = {0.1, 0, 0};
  BoardMounting m;
  m.q_BI = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ());  // I's x = B's y
  MagneticSpec mag;
  mag.field_N_uT = {0, 30, -40};
  mag.hard_iron_I_uT = {1, 2, 3};
  const IdealImu i = IdealImuFromTruth(x, m, mag);
  EXPECT_NEAR(i.f_I_mps2.y(), -1.0, 1e-12);
  EXPECT_NEAR(i.w_I_radps.y(), -0.1, 1e-12);
  EXPECT_NEAR(i.mag_I_uT.x(), 30 + 1, 1e-12);  // north is B's y = I's x
  EXPECT_NEAR(i.mag_I_uT.z(), -40 + 3, 1e-12);
}

TEST(SensorSpecTest, ProfilesExistAndUnknownNamesThrow) {
  for (const std::string& n : ProfileNames()) EXPECT_EQ(ProfileByName(n).name, n);
  EXPECT_THROW(ProfileByName("nope"), std::invalid_argument);
  EXPECT_NEAR(ProfileByName("razor-v13").gyro.counts.output_lsb() / kDeg, 0.0604853, 1e-6);
}

}  // namespace
}  // namespace hil::mcu

#include "hil/firmware_emu/mcu/sensor_spec.h"

#include <numbers>
#include <stdexcept>

#include "hil/firmware_emu/angles.h"
#include "hil/firmware_emu/truth_sample.h"

namespace hil::mcu {
namespace {

constexpr double kG = kStandardGravity_mps2;
constexpr double kDegPerHour = kDeg / 3600.0;
constexpr double kMicroG = 1e-6 * kG;

// Symmetric 16-bit digital output with `lsb` per count and saturation at `range`.
TriadCountSpec Digital16(double lsb, double range) {
  TriadCountSpec c;
  c.count_lsb = lsb;
  c.range = range;
  return c;
}

// ---- seed 000: SparkFun 9DOF Razor IMU v13 (estimators.md §5.1–5.4) ----
ImuProfile RazorV13() {
  ImuProfile p;
  p.name = "razor-v13";
  p.id = 0;
  p.default_baud = 57600;  // stock firmware default and maximum at 8 MHz
  p.mag_rate_hz = 10;      // HMC5843 default output rate

  // ADXL345, full resolution ±2 g (3.9 mg/LSB), ODR 100 Hz (bandwidth 50 Hz), read over I²C at the
  // sample instant (point sampling: engine vibration aliases, as the seed paper observed).
  auto& a = p.accel;
  a.error.noise_density = Eigen::Vector3d(290, 290, 430) * kMicroG;
  a.error.bias_instability = 100 * kMicroG;
  a.error.bias_correlation_time_s = 100;
  a.error.turn_on_bias_sigma = Eigen::Vector3d(40e-3, 40e-3, 80e-3) * kG;
  a.error.scale_factor_sigma_ppm = 10000;
  a.error.misalignment_sigma_rad = 0.5 * kDeg;
  a.error.bandwidth_hz = 50;
  a.error.bias_temperature_coeff_per_c = 0.8e-3 * kG;
  a.counts.count_lsb = kG / 256.0;
  a.counts.range = 2.0 * kG;
  a.counts.count_min = -512;
  a.counts.count_max = 511;
  a.sampling = Sampling::kPoint;

  // LPR530AL (x, y) and LY530AL (z), 4×OUT 3.33 mV/(°/s), ±300 °/s, read by the ATmega328's
  // 10-bit ADC at 3.3 V (3.22 mV/count); 16 conversions summed over each sample period.
  auto& g = p.gyro;
  g.error.noise_density = Eigen::Vector3d::Constant(0.035 * kDeg);
  g.error.bias_instability = 100 * kDegPerHour;
  g.error.bias_correlation_time_s = 100;
  g.error.turn_on_bias_sigma = Eigen::Vector3d::Constant(2.0 * kDeg);
  g.error.scale_factor_sigma_ppm = 20000;
  g.error.misalignment_sigma_rad = 0.5 * kDeg;
  g.error.bandwidth_hz = 140;
  g.error.bias_temperature_coeff_per_c = 0.03 * kDeg;
  g.counts.count_lsb = (3.3 / 1024.0) / 3.33e-3 * kDeg;
  g.counts.range = 300 * kDeg;
  g.counts.count_min = 0;
  g.counts.count_max = 1023;
  g.counts.zero_count = 1.23 / 3.3 * 1024.0;  // zero-rate level 1.23 V
  g.counts.nominal_zero_count = 382;
  g.counts.oversample = 16;
  g.counts.conversion_noise_counts = 0.5;
  g.sampling = Sampling::kAverage;

  // HMC5843, gain 1.0 Ga (1300 counts/Ga = 100/1300 µT), 12-bit, overflow −4096, 10 Hz.
  auto& m = p.mag;
  m.error.noise_density = Eigen::Vector3d::Constant(0.1);
  m.error.scale_factor_sigma_ppm = 10000;
  m.error.misalignment_sigma_rad = 0.5 * kDeg;
  m.error.bandwidth_hz = 5;
  m.counts.count_lsb = 100.0 / 1300.0;
  m.counts.count_min = -2048;
  m.counts.count_max = 2047;
  m.counts.has_overflow_value = true;
  m.counts.overflow_value = -4096;
  m.sampling = Sampling::kPoint;
  return p;
}

TriadSpec GenericMag(double lsb) {
  TriadSpec m;
  m.error.noise_density = Eigen::Vector3d::Constant(0.1);
  m.error.scale_factor_sigma_ppm = 5000;
  m.error.misalignment_sigma_rad = 0.2 * kDeg;
  m.error.bandwidth_hz = 20;
  m.counts = Digital16(lsb, 3000);
  m.sampling = Sampling::kPoint;
  return m;
}

// ---- grades: figures of estimators.md §6 ----
ImuProfile ConsumerMems() {  // MPU-6000 class
  ImuProfile p;
  p.name = "consumer-mems";
  p.id = 1;
  p.accel.error.noise_density = Eigen::Vector3d::Constant(400 * kMicroG);
  p.accel.error.bias_instability = 36 * kMicroG;
  p.accel.error.bias_correlation_time_s = 800;
  p.accel.error.turn_on_bias_sigma = Eigen::Vector3d::Constant(20e-3 * kG);
  p.accel.error.scale_factor_sigma_ppm = 5000;
  p.accel.error.misalignment_sigma_rad = 0.3 * kDeg;
  p.accel.error.bandwidth_hz = 94;
  p.accel.counts = Digital16(kG / 4096.0, 8 * kG);
  p.gyro.error.noise_density = Eigen::Vector3d::Constant(0.3 / 60.0 * kDeg);  // ARW 0.3 °/√h
  p.gyro.error.bias_instability = 4.6 * kDegPerHour;
  p.gyro.error.bias_correlation_time_s = 500;
  p.gyro.error.turn_on_bias_sigma = Eigen::Vector3d::Constant(0.5 * kDeg);
  p.gyro.error.scale_factor_sigma_ppm = 5000;
  p.gyro.error.misalignment_sigma_rad = 0.3 * kDeg;
  p.gyro.error.bandwidth_hz = 98;
  p.gyro.counts = Digital16(kDeg / 16.4, 2000 * kDeg);
  p.mag = GenericMag(0.15);
  return p;
}

ImuProfile IndustrialMems() {  // ADIS16465 class
  ImuProfile p;
  p.name = "industrial-mems";
  p.id = 2;
  p.accel.error.noise_density = Eigen::Vector3d::Constant(0.012 / 60.0);  // VRW 0.012 m/s/√h
  p.accel.error.bias_instability = 3.6 * kMicroG;
  p.accel.error.bias_correlation_time_s = 300;
  p.accel.error.turn_on_bias_sigma = Eigen::Vector3d::Constant(2e-3 * kG);
  p.accel.error.scale_factor_sigma_ppm = 500;
  p.accel.error.misalignment_sigma_rad = 0.05 * kDeg;
  p.accel.error.bandwidth_hz = 300;
  p.accel.counts = Digital16(kG / 4000.0, 8 * kG);
  p.gyro.error.noise_density = Eigen::Vector3d::Constant(0.15 / 60.0 * kDeg);  // ARW 0.15 °/√h
  p.gyro.error.bias_instability = 2 * kDegPerHour;
  p.gyro.error.bias_correlation_time_s = 300;
  p.gyro.error.turn_on_bias_sigma = Eigen::Vector3d::Constant(0.05 * kDeg);
  p.gyro.error.scale_factor_sigma_ppm = 500;
  p.gyro.error.misalignment_sigma_rad = 0.05 * kDeg;
  p.gyro.error.bandwidth_hz = 300;
  p.gyro.counts = Digital16(0.015 * kDeg, 480 * kDeg);
  p.mag = GenericMag(0.1);
  return p;
}

ImuProfile Tactical() {  // HG1700 / ADIS16488 class
  ImuProfile p;
  p.name = "tactical";
  p.id = 3;
  p.accel.error.noise_density = Eigen::Vector3d::Constant(0.01 / 60.0);  // VRW 0.01 m/s/√h
  p.accel.error.bias_instability = 50 * kMicroG;
  p.accel.error.bias_correlation_time_s = 300;
  p.accel.error.turn_on_bias_sigma = Eigen::Vector3d::Constant(1e-3 * kG);
  p.accel.error.scale_factor_sigma_ppm = 300;
  p.accel.error.misalignment_sigma_rad = 0.01 * kDeg;
  p.accel.error.bandwidth_hz = 500;
  p.accel.counts = Digital16(kG / 8000.0, 4 * kG);
  p.gyro.error.noise_density = Eigen::Vector3d::Constant(0.1 / 60.0 * kDeg);  // ARW 0.1 °/√h
  p.gyro.error.bias_instability = 1 * kDegPerHour;
  p.gyro.error.bias_correlation_time_s = 300;
  p.gyro.error.turn_on_bias_sigma = Eigen::Vector3d::Constant(0.01 * kDeg);
  p.gyro.error.scale_factor_sigma_ppm = 150;
  p.gyro.error.misalignment_sigma_rad = 0.01 * kDeg;
  p.gyro.error.bandwidth_hz = 500;
  p.gyro.counts = Digital16(0.01 * kDeg, 327 * kDeg);
  p.mag = GenericMag(0.1);
  return p;
}

}  // namespace

const std::vector<std::string>& ProfileNames() {
  static const std::vector<std::string> names{"razor-v13", "consumer-mems", "industrial-mems",
                                              "tactical"};
  return names;
}

ImuProfile ProfileByName(const std::string& name) {
  if (name == "razor-v13") return RazorV13();
  if (name == "consumer-mems") return ConsumerMems();
  if (name == "industrial-mems") return IndustrialMems();
  if (name == "tactical") return Tactical();
  throw std::invalid_argument("unknown IMU profile '" + name + "'");
}

}  // namespace hil::mcu

#include "hil/firmware_emu/mcu/vibration_source.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hil::mcu {
namespace {
constexpr double kCrankTwoPi = 2.0 * std::numbers::pi;
}

VibrationSource::VibrationSource(const RoughImuSpec& spec, std::uint64_t seed)
    : rng_(seed), ride_reference_speed_mps_(spec.ride_reference_speed_mps) {
  if (ride_reference_speed_mps_ < 0)
    throw std::invalid_argument("vibration: ride_reference_speed_mps must be >= 0");
  const double fs = spec.internal_rate_hz;
  if (!(fs > 0)) throw std::invalid_argument("vibration: internal_rate_hz must be > 0");
  for (const EngineOrder& e : spec.engine_orders) {
    Order o{e.order, {1.0, 0.0}, {1.0, 0.0}, {}, {}, {}, {}};
    for (int i = 0; i < 3; ++i) {
      const double pa = kCrankTwoPi * rng_.Uniform();
      const double pg = kCrankTwoPi * rng_.Uniform();
      o.accel_re[i] = e.accel_amplitude_mps2[i] * std::cos(pa);
      o.accel_im[i] = e.accel_amplitude_mps2[i] * std::sin(pa);
      o.gyro_re[i] = e.gyro_amplitude_radps[i] * std::cos(pg);
      o.gyro_im[i] = e.gyro_amplitude_radps[i] * std::sin(pg);
    }
    orders_.push_back(o);
  }
  double f_top = 0;
  for (const RideBand& r : spec.ride) {
    if (!(r.f_low_hz > 0 && r.f_low_hz < r.f_high_hz && r.f_high_hz < 0.5 * fs))
      throw std::invalid_argument("vibration: a ride band must satisfy 0 < f_low < f_high < fs/2");
    f_top = std::max(f_top, r.f_high_hz);
  }
  if (f_top > 0) ride_decimation_ = std::max(1, static_cast<int>(fs / (16.0 * f_top)));
  const double fs_ride = fs / ride_decimation_;
  for (const RideBand& r : spec.ride) {
    Band b{};
    // white noise of one-sided PSD S sampled at fs_ride has variance S·fs_ride/2
    b.accel_sigma = (r.accel_psd_mps2_sq_per_hz * (0.5 * fs_ride)).cwiseSqrt();
    b.gyro_sigma = (r.gyro_psd_radps_sq_per_hz * (0.5 * fs_ride)).cwiseSqrt();
    b.accel_hp = b.gyro_hp = Biquad3::ButterworthHighPass(r.f_low_hz, fs_ride);
    b.accel_lp = b.gyro_lp = Biquad3::ButterworthLowPass(r.f_high_hz, fs_ride);
    bands_.push_back(b);
  }
  if (spec.mount.frequency_hz > 0) {
    mount_enabled_ = true;
    accel_mount_ = gyro_mount_ =
        Biquad3::MountTransmissibility(spec.mount.frequency_hz, spec.mount.damping_ratio, fs);
  }
}

void VibrationSource::SetRpm(double rpm, double dt_s) {
  crank_radps_ = rpm / 60.0 * kCrankTwoPi;
  dt_s_ = dt_s;
  for (Order& o : orders_) {
    o.phasor = std::polar(1.0, o.order * crank_rad_);
    o.rotation = std::polar(1.0, o.order * crank_radps_ * dt_s);
  }
}

void VibrationSource::SetGroundSpeed(double speed_mps) {
  if (ride_reference_speed_mps_ > 0)
    ride_drive_scale_ = std::sqrt(std::abs(speed_mps) / ride_reference_speed_mps_);
}

double VibrationSource::UniformUnitVariance() {
  // uniform on [−√3, √3): unit variance; the band filters sum many draws, so their output is
  // Gaussian to a good approximation (central limit) at a fraction of a normal draw's cost
  return (2.0 * rng_.Uniform() - 1.0) * std::numbers::sqrt3;
}

void VibrationSource::NextRideSample() {
  ride_f_prev_ = ride_f_next_;
  ride_w_prev_ = ride_w_next_;
  ride_f_next_.setZero();
  ride_w_next_.setZero();
  for (Band& b : bands_) {
    Eigen::Vector3d na, ng;
    // the drive, not the output, is scaled: the band filters carry the ride smoothly through a
    // change of speed (their state is the terrain already driven over)
    for (int i = 0; i < 3; ++i) na[i] = ride_drive_scale_ * UniformUnitVariance();
    for (int i = 0; i < 3; ++i) ng[i] = ride_drive_scale_ * UniformUnitVariance();
    ride_f_next_ += b.accel_lp.Step(b.accel_hp.Step(b.accel_sigma.cwiseProduct(na)));
    ride_w_next_ += b.gyro_lp.Step(b.gyro_hp.Step(b.gyro_sigma.cwiseProduct(ng)));
  }
}

void VibrationSource::Step(Eigen::Vector3d& f_I_mps2, Eigen::Vector3d& w_I_radps) {
  crank_rad_ += crank_radps_ * dt_s_;
  f_I_mps2.setZero();
  w_I_radps.setZero();
  // a stopped engine does not vibrate (the phasors would otherwise freeze into an offset)
  const bool turning = crank_radps_ != 0;
  for (Order& o : orders_) {
    if (!turning) break;
    // written out: std::complex's operator* calls __muldc3 (NaN rules) without -ffast-math
    const double re = o.phasor.real() * o.rotation.real() - o.phasor.imag() * o.rotation.imag();
    const double im = o.phasor.real() * o.rotation.imag() + o.phasor.imag() * o.rotation.real();
    o.phasor = {re, im};
    const double c = o.phasor.real(), s = o.phasor.imag();
    // Im(e^{ja} · A e^{jφ}) = A sin(a + φ)
    f_I_mps2 += c * o.accel_im + s * o.accel_re;
    w_I_radps += c * o.gyro_im + s * o.gyro_re;
  }
  if (!bands_.empty()) {
    if (ride_phase_ == 0) NextRideSample();
    ++ride_phase_;
    const double u = static_cast<double>(ride_phase_) / ride_decimation_;
    f_I_mps2 += ride_f_prev_ + u * (ride_f_next_ - ride_f_prev_);
    w_I_radps += ride_w_prev_ + u * (ride_w_next_ - ride_w_prev_);
    if (ride_phase_ == ride_decimation_) ride_phase_ = 0;
  }
  if (mount_enabled_) {
    f_I_mps2 = accel_mount_.Step(f_I_mps2);
    w_I_radps = gyro_mount_.Step(w_I_radps);
  }
}

}  // namespace hil::mcu

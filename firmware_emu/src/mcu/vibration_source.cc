#include "hil/firmware_emu/mcu/vibration_source.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hil::mcu {
namespace {
constexpr double kCrankTwoPi = 2.0 * std::numbers::pi;
}

VibrationSource::VibrationSource(const RoughImuSpec& spec, std::uint64_t seed) : rng_(seed) {
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
  for (const RideBand& r : spec.ride) {
    if (!(r.f_low_hz > 0 && r.f_low_hz < r.f_high_hz && r.f_high_hz < 0.5 * fs))
      throw std::invalid_argument("vibration: a ride band must satisfy 0 < f_low < f_high < fs/2");
    Band b{};
    // white noise of one-sided PSD S sampled at fs has variance S·fs/2
    b.accel_sigma = (r.accel_psd_mps2_sq_per_hz * (0.5 * fs)).cwiseSqrt();
    b.gyro_sigma = (r.gyro_psd_radps_sq_per_hz * (0.5 * fs)).cwiseSqrt();
    b.accel_hp = b.gyro_hp = Biquad3::ButterworthHighPass(r.f_low_hz, fs);
    b.accel_lp = b.gyro_lp = Biquad3::ButterworthLowPass(r.f_high_hz, fs);
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

double VibrationSource::UniformUnitVariance() {
  // uniform on [−√3, √3): unit variance; the band filters sum many draws, so their output is
  // Gaussian to a good approximation (central limit) at a fraction of a normal draw's cost
  return (2.0 * rng_.Uniform() - 1.0) * std::numbers::sqrt3;
}

void VibrationSource::Step(Eigen::Vector3d& f_I_mps2, Eigen::Vector3d& w_I_radps) {
  crank_rad_ += crank_radps_ * dt_s_;
  f_I_mps2.setZero();
  w_I_radps.setZero();
  // a stopped engine does not vibrate (the phasors would otherwise freeze into an offset)
  const bool turning = crank_radps_ != 0;
  for (Order& o : orders_) {
    if (!turning) break;
    o.phasor *= o.rotation;
    const double c = o.phasor.real(), s = o.phasor.imag();
    // Im(e^{ja} · A e^{jφ}) = A sin(a + φ)
    f_I_mps2 += c * o.accel_im + s * o.accel_re;
    w_I_radps += c * o.gyro_im + s * o.gyro_re;
  }
  for (Band& b : bands_) {
    Eigen::Vector3d na, ng;
    for (int i = 0; i < 3; ++i) na[i] = UniformUnitVariance();
    for (int i = 0; i < 3; ++i) ng[i] = UniformUnitVariance();
    f_I_mps2 += b.accel_lp.Step(b.accel_hp.Step(b.accel_sigma.cwiseProduct(na)));
    w_I_radps += b.gyro_lp.Step(b.gyro_hp.Step(b.gyro_sigma.cwiseProduct(ng)));
  }
  if (mount_enabled_) {
    f_I_mps2 = accel_mount_.Step(f_I_mps2);
    w_I_radps = gyro_mount_.Step(w_I_radps);
  }
}

}  // namespace hil::mcu

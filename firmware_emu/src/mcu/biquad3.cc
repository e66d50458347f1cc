#include "hil/firmware_emu/mcu/biquad3.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace hil::mcu {
namespace {

// Bilinear transform of the analog section (n2 s² + n1 s + n0)/(s² + d1 s + d0) with s =
// k(z−1)/(z+1).
Biquad3 BilinearSection(double n2, double n1, double n0, double d1, double d0, double k) {
  const double a0 = k * k + d1 * k + d0;
  return {(n2 * k * k + n1 * k + n0) / a0, (2.0 * n0 - 2.0 * n2 * k * k) / a0,
          (n2 * k * k - n1 * k + n0) / a0, (2.0 * d0 - 2.0 * k * k) / a0,
          (k * k - d1 * k + d0) / a0};
}

// The bilinear constant that maps analog ωa onto digital frequency f (prewarping).
double PrewarpBilinearK(double f_hz, double fs_hz, double& w_a) {
  if (!(f_hz > 0 && f_hz < 0.5 * fs_hz))
    throw std::invalid_argument("Biquad3: frequency must be in (0, fs/2)");
  w_a = 2.0 * std::numbers::pi * f_hz;
  return w_a / std::tan(std::numbers::pi * f_hz / fs_hz);
}

}  // namespace

Biquad3 Biquad3::ButterworthLowPass(double fc_hz, double fs_hz) {
  double w = 0;
  const double k = PrewarpBilinearK(fc_hz, fs_hz, w);
  return BilinearSection(0, 0, w * w, std::numbers::sqrt2 * w, w * w, k);
}

Biquad3 Biquad3::ButterworthHighPass(double fc_hz, double fs_hz) {
  double w = 0;
  const double k = PrewarpBilinearK(fc_hz, fs_hz, w);
  return BilinearSection(1, 0, 0, std::numbers::sqrt2 * w, w * w, k);
}

Biquad3 Biquad3::MountTransmissibility(double fn_hz, double zeta, double fs_hz) {
  if (!(zeta > 0)) throw std::invalid_argument("Biquad3: damping ratio must be > 0");
  double w = 0;
  const double k = PrewarpBilinearK(fn_hz, fs_hz, w);
  return BilinearSection(0, 2.0 * zeta * w, w * w, 2.0 * zeta * w, w * w, k);
}

void Biquad3::Settle(const Eigen::Vector3d& x) {
  const double dc = (b0_ + b1_ + b2_) / (1.0 + a1_ + a2_);
  const Eigen::Vector3d y = dc * x;
  z2_ = b2_ * x - a2_ * y;
  z1_ = b1_ * x - a1_ * y + z2_;
}

double Biquad3::Gain(double f_hz, double fs_hz) const {
  const std::complex<double> z1 = std::polar(1.0, -2.0 * std::numbers::pi * f_hz / fs_hz);
  const std::complex<double> z2 = z1 * z1;
  return std::abs((b0_ + b1_ * z1 + b2_ * z2) / (1.0 + a1_ * z1 + a2_ * z2));
}

}  // namespace hil::mcu

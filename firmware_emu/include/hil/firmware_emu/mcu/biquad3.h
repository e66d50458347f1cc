#pragma once
/// @file
/// A second-order IIR section (direct form II transposed) run on three axes at once, with the
/// bilinear-transform designs the IMU front end needs: Butterworth low- and high-pass, and the
/// base-excitation transmissibility of a mount resonance. Coefficients are normalised (a0 = 1).

#include <Eigen/Core>

namespace hil::mcu {

class Biquad3 {
 public:
  /// Identity filter (passes the input through).
  Biquad3() = default;
  Biquad3(double b0, double b1, double b2, double a1, double a2)
      : b0_(b0), b1_(b1), b2_(b2), a1_(a1), a2_(a2) {}

  /// Second-order Butterworth low-pass at cutoff `fc_hz` for sample rate `fs_hz` (prewarped).
  static Biquad3 ButterworthLowPass(double fc_hz, double fs_hz);
  /// Second-order Butterworth high-pass at `fc_hz`.
  static Biquad3 ButterworthHighPass(double fc_hz, double fs_hz);
  /// Base-excitation transmissibility of a mass on a spring and damper: natural frequency
  /// `fn_hz`, damping ratio `zeta` (prewarped at fn).
  static Biquad3 MountTransmissibility(double fn_hz, double zeta, double fs_hz);

  Eigen::Vector3d Step(const Eigen::Vector3d& x) {
    const Eigen::Vector3d y = b0_ * x + z1_;
    z1_ = b1_ * x - a1_ * y + z2_;
    z2_ = b2_ * x - a2_ * y;
    return y;
  }
  /// Sets the state to the steady state of a constant input `x` (no start-up transient).
  void Settle(const Eigen::Vector3d& x);
  /// |H(e^{jωT})| at frequency f_hz for sample rate fs_hz.
  double Gain(double f_hz, double fs_hz) const;

 private:
  double b0_ = 1, b1_ = 0, b2_ = 0, a1_ = 0, a2_ = 0;
  Eigen::Vector3d z1_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d z2_ = Eigen::Vector3d::Zero();
};

}  // namespace hil::mcu

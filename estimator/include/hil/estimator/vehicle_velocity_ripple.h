#pragma once
/// @file
/// The vehicle-frame velocity ripple that the INS's own propagation carries above a second-order
/// low-pass: what the non-holonomic constraint and the speed model must leave out of their
/// innovations (`[filter] vehicle_lowpass_tau_s`; estimator.md, "Vibration and the vehicle model").
///
/// Why: on a vibrating vehicle (ride, 1–15 Hz) the body's velocity oscillates by centimetres per
/// second about the chassis's slow motion, and a sound INS follows it. The speed model (a set speed
/// within 5 mm/s) and the NHC (2 cm/s) describe the slow motion only; fed the INS's instantaneous
/// velocity at 10 Hz they take the ripple for a velocity error, and during a GNSS outage, where
/// the position error is the integral of the velocity error (P_pv ≈ t·P_vv), each update moves
/// the position by up to t × the ripple (tractor_engine_vibration, seed 4: ±3 cm within 0.1 s at
/// the end of a 10 s outage, field_realism/README "Session ride").
///
/// The filter: x1 = v − lp1, x2 = v − lp2 of a critically damped low-pass (two first-order stages
/// of time constant tau_s) driven by the propagation's velocity change Δv only:
///   x1 ← (x1 + Δv)(1 − a),  x2 ← x2 + Δv − a·(x2 + Δv − x1),  a = dt / (tau_s + dt).
/// A filter update (GNSS, NHC, ...) shifts v and both low-passes alike, so it leaves x1, x2 as they
/// are: only the motion the IMU propagated is low-passed, not the corrections. The constraints use
/// v − x2 = lp2(v): a ripple at f is left with |H| = 1/(1 + (2π f tau_s)²) (tau_s 0.5 s: 0.09 at
/// 1 Hz, 0.04 at 1.5 Hz); a slow velocity passes with a lag of 2·tau_s (a speed change of a m/s²
/// leaves 2·tau_s·a). Fixed size, no allocation.

#include <Eigen/Core>

namespace hil::estimator {

class VehicleVelocityRipple {
 public:
  VehicleVelocityRipple() = default;
  /// tau_s ≤ 0: off (ripple() stays zero).
  explicit VehicleVelocityRipple(double tau_s) : tau_s_(tau_s) {}

  bool enabled() const { return tau_s_ > 0; }
  /// One propagation step: the vehicle-frame velocity changed by dv_V_mps over dt_s.
  void Propagate(const Eigen::Vector3d& dv_V_mps, double dt_s);
  /// The ripple v − lp2(v) in the vehicle frame, m/s.
  const Eigen::Vector3d& ripple_V_mps() const { return x2_; }
  void Reset() { x1_.setZero(), x2_.setZero(); }

 private:
  double tau_s_ = 0;
  Eigen::Vector3d x1_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d x2_ = Eigen::Vector3d::Zero();
};

}  // namespace hil::estimator

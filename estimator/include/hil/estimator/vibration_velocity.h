#pragma once
/// @file
/// The IMU's vibration velocity and its variance: the part of the body velocity that the IMU's own
/// specific force puts above the corner of `tau_s` (ride vibration, engine orders), which the
/// vehicle-model pseudo-measurements (non-holonomic constraint, speed model) must allow for.
///
/// Why: the non-holonomic constraint and the speed model describe the chassis's slow motion. An IMU
/// on a vibrating vehicle integrates its vibration into the INS velocity: on the tractor rig of
/// field_realism/tractor_engine_vibration.yaml the 1–15 Hz ride gives 0.029 / 0.026 / 0.045 m/s
/// r.m.s. (x / y / z, measured on the capture) against the speed model's 5 mm/s and the NHC's
/// 2 cm/s. Each 10 Hz pseudo-measurement then takes the ripple for an error of the velocity, the
/// tilt and the accelerometer bias, which an outage integrates (estimator.md, "Vibration and the
/// vehicle model"). Their noise therefore gets this variance added, per body axis.
///
/// The filter: a first-order low-pass of the specific force (time constant tau_s) takes off gravity
/// and the vehicle's own slow accelerations; the rest is integrated with the same leak, and its
/// square averaged over `mean_tau_s`:
///   f̄ ← f̄ + a·(f − f̄),  v ← (1 − a)·v + (f − f̄)·dt,  a = dt / (tau_s + dt),
///   σ² ← σ² + b·(v² − σ²),  b = dt / (mean_tau_s + dt).
/// Its gain on a ripple at f is (f/f_c)² / (1 + (f/f_c)²), f_c = 1/(2π tau_s): 0.91 at 1 Hz for
/// 0.5 s. White sensor noise of density q gives σ² ≈ q²·tau_s/4 (the industrial MEMS: 1 mm/s,
/// nothing beside the NHC's 2 cm/s). Fixed size, no allocation.

#include <Eigen/Core>

namespace hil::estimator {

class VibrationVelocity {
 public:
  VibrationVelocity() = default;
  /// tau_s ≤ 0: off (the variance stays zero).
  VibrationVelocity(double tau_s, double mean_tau_s) : tau_s_(tau_s), mean_tau_s_(mean_tau_s) {}

  /// One IMU interval: its raw velocity increment (body frame) over dt_s.
  void Add(const Eigen::Vector3d& delta_velocity_B_mps, double dt_s);
  /// The vibration velocity in the body frame after the last Add, and its mean square per axis.
  const Eigen::Vector3d& velocity_B_mps() const { return v_B_mps_; }
  const Eigen::Vector3d& variance_B_mps2() const { return var_B_mps2_; }
  bool enabled() const { return tau_s_ > 0; }

 private:
  double tau_s_ = 0;
  double mean_tau_s_ = 0;
  bool started_ = false;
  Eigen::Vector3d mean_f_B_mps2_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_B_mps_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d var_B_mps2_ = Eigen::Vector3d::Zero();
};

}  // namespace hil::estimator

#pragma once
/// @file
/// The accelerometer's white-noise density as its own samples show it: the scatter of the first
/// difference of the specific force, f_k − f_{k−1}, which has 2 σ² for white noise of per-sample σ
/// and passes the vehicle's own slow accelerations hardly at all (gain
/// (2 sin(π f / f_s))²: 0.004 for a 2 Hz walking step at 200 Hz, 2.6 for an engine's 23 Hz
/// aliased to 3 Hz at 10 Hz). Density² = σ² · dt per axis, averaged over
/// `tau_s`. Why: a vibrating board read by point sampling below its vibration's frequency
/// (paper 000's Razor at 10 Hz on a 23 Hz engine) aliases the vibration into the band the INS
/// integrates, an error the configured density (the sensor's data sheet) does not hold; the filter
/// then trusts its INS between fixes far more than it should and cannot tell its own drift from
/// the receiver's time-correlated error. Fixed size, no allocation.

#include <Eigen/Core>

namespace hil::estimator {

class AccelScatter {
 public:
  AccelScatter() = default;
  /// tau_s ≤ 0: off (the density stays zero). Samples at a rate above max_rate_hz are not
  /// counted: read out that fast, a vehicle's vibration is measured, not aliased, and the scatter
  /// is the motion the INS integrates rightly (a walker's steps at 152 Hz on walk_0827: taken for
  /// noise, its 15 s outages' worst error went 2.8 → 8.3 m).
  explicit AccelScatter(double tau_s, double max_rate_hz = 50.0)
      : tau_s_(tau_s), min_dt_s_(max_rate_hz > 0 ? 1.0 / max_rate_hz : 0.0) {}

  /// One IMU interval: its velocity increment (body frame) over dt_s.
  void Add(const Eigen::Vector3d& delta_velocity_B_mps, double dt_s);
  /// The white-noise density² (m²/s³) the scatter shows, the largest axis's; 0 until warmed up.
  double density2_m2ps3() const { return samples_ >= kWarmup ? axes_.maxCoeff() : 0.0; }
  /// The same per body axis: the filter floors each axis's density and rotates them into the
  /// navigation frame (an engine shaking the board along z must not flood the horizontal INS:
  /// paper 000's Razor, 0.31 m/s²/√Hz along z against 0.10 along x).
  Eigen::Vector3d density2_B_m2ps3() const {
    return samples_ >= kWarmup ? axes_ : Eigen::Vector3d::Zero();
  }
  bool enabled() const { return tau_s_ > 0; }

 private:
  static constexpr int kWarmup = 50;
  double tau_s_ = 0;
  double min_dt_s_ = 0;
  Eigen::Vector3d f1_ = Eigen::Vector3d::Zero();
  int samples_ = 0;
  Eigen::Vector3d axes_ = Eigen::Vector3d::Zero();  // per axis, averaged over tau_s
};

}  // namespace hil::estimator

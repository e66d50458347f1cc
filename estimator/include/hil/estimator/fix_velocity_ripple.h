#pragma once
/// @file
/// The part of the INS's velocity ripple that a GNSS fix velocity sees at every fix alike: what the
/// velocity update must leave out of its innovation (estimator.md, "The INS's ripple at the fix
/// instants").
///
/// Why: a board read by point sampling below its vibration's frequency (paper 000's Razor at 10 Hz
/// on a 23 Hz engine) aliases the vibration into a tone in band (3 Hz) that the INS integrates into
/// a velocity ripple of A/(2π f) (2 cm/s for 0.4 m/s²), a sensor artefact: the receiver's Doppler
/// velocity has no such ripple. When the tone's frequency is near a multiple of the fix rate (3 Hz
/// at 1 Hz: a governed engine's steady RPM) the fixes sample the ripple at the same phase every
/// time, and the filter reads a velocity error that stays for minutes (40 ppm: 0.001 cycles a
/// second), contradicted by the position fixes: it pushes the velocity, tilt and bias off instead.
///
/// The estimate, from u(t), the INS's own (unaided) velocity change since the previous fix
/// velocity, over the interval T between them: r = u(t)/2 − (1/T)∫u dt, the propagated velocity's
/// trapezoid end mean less its time mean. It is zero for any velocity that changes linearly over T
/// (a constant acceleration, the INS's slow drift from tilt and bias), r(t) for a ripple periodic
/// in T (stroboscopic: exactly the part the fixes see alike), zero for one at a half-integer number
/// of periods per T (its sign alternates from fix to fix and averages out anyway). For white
/// accelerometer noise of density q it removes a variance of q²T/12 from the comparison.
/// Fixed size, no allocation.

#include <Eigen/Core>

namespace hil::estimator {

class FixVelocityRipple {
 public:
  /// One IMU interval: the INS's own velocity change (navigation frame) over dt_s.
  void Add(const Eigen::Vector3d& dv_N_mps, double dt_s);
  /// The ripple at the end of the interval since the last Restart (zero before any interval, or
  /// when the interval exceeds max_interval_s: a gap, over which the INS's drift is not linear).
  Eigen::Vector3d Ripple_N_mps(double max_interval_s) const;
  /// A fix velocity was fused: the next interval starts here.
  void Restart();

 private:
  Eigen::Vector3d u_N_mps_ = Eigen::Vector3d::Zero();       // velocity change since Restart
  Eigen::Vector3d integral_N_m_ = Eigen::Vector3d::Zero();  // ∫ u dt (trapezoid)
  double interval_s_ = 0;
};

}  // namespace hil::estimator

// The INS's velocity ripple as the fix velocities see it (fix_velocity_ripple.h).
#include "hil/estimator/fix_velocity_ripple.h"

namespace hil::estimator {

void FixVelocityRipple::Add(const Eigen::Vector3d& dv_N_mps, double dt_s) {
  if (!(dt_s > 0) || !dv_N_mps.allFinite()) return;
  const Eigen::Vector3d u0 = u_N_mps_;
  u_N_mps_ += dv_N_mps;
  integral_N_m_ += 0.5 * (u0 + u_N_mps_) * dt_s;
  interval_s_ += dt_s;
}

Eigen::Vector3d FixVelocityRipple::Ripple_N_mps(double max_interval_s) const {
  if (!(interval_s_ > 0) || interval_s_ > max_interval_s) return Eigen::Vector3d::Zero();
  return 0.5 * u_N_mps_ - integral_N_m_ / interval_s_;
}

void FixVelocityRipple::Restart() {
  u_N_mps_.setZero();
  integral_N_m_.setZero();
  interval_s_ = 0;
}

}  // namespace hil::estimator

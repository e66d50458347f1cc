// The vehicle-frame velocity ripple above a critically damped low-pass of the INS's propagation
// (vehicle_velocity_ripple.h).
#include "hil/estimator/vehicle_velocity_ripple.h"

namespace hil::estimator {

void VehicleVelocityRipple::Propagate(const Eigen::Vector3d& dv_V_mps, double dt_s) {
  if (!enabled() || !(dt_s > 0)) return;
  const double a = dt_s / (tau_s_ + dt_s);
  // v moves by dv; lp1 and lp2 then follow by a of their distance (lp2 towards the new lp1)
  x1_ = (x1_ + dv_V_mps) * (1.0 - a);
  const Eigen::Vector3d x2 = x2_ + dv_V_mps;
  x2_ = x2 - a * (x2 - x1_);
}

}  // namespace hil::estimator

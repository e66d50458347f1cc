#include "hil/firmware_emu/gnss/gnss_fix.h"

#include <cmath>
#include <numbers>

namespace hil::gnss {

double GnssFix::ground_speed_mps() const { return std::hypot(vel_n_mps, vel_e_mps); }

double GnssFix::course_deg() const {
  double c = std::atan2(vel_e_mps, vel_n_mps) * 180.0 / std::numbers::pi;
  if (c < 0) c += 360.0;
  return c;
}

}  // namespace hil::gnss

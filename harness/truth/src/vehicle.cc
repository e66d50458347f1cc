#include "hil/truth/vehicle.h"

namespace hil::truth {

VehicleParams VehicleParams::GreenhousePlatform() { return VehicleParams{}; }

VehicleParams VehicleParams::Tractor() {
  VehicleParams p;
  p.wheelbase_m = 2.3;
  p.track_m = 1.6;
  p.max_steer_deg = 35;
  p.max_steer_rate_dps = 20;
  p.steer_lag_s = 0.3;
  p.speed_lag_s = 1.0;
  return p;
}

VehicleParams VehicleParams::DiffDrive() {
  VehicleParams p;
  p.model = Model::kDiffDrive;
  p.track_m = 0.5;
  p.speed_lag_s = 0.3;
  p.yaw_rate_lag_s = 0.2;
  p.max_yaw_rate_dps = 45;
  return p;
}

}  // namespace hil::truth

#include "hil/estimator/guidance/vehicle.h"

#include <algorithm>
#include <cmath>

namespace hil::estimator::guidance {

double FrontSteeredPlatform::SteerAngleFromCurvature(double curvature_left_per_m) const {
  return std::clamp(std::atan(curvature_left_per_m * wheelbase_m), -max_steer_rad, max_steer_rad);
}

double FrontSteeredPlatform::CurvatureFromSteerAngle(double steer_left_rad) const {
  return std::tan(steer_left_rad) / wheelbase_m;
}

double FrontSteeredPlatform::Reachable(double curvature_left_per_m) const {
  return CurvatureFromSteerAngle(SteerAngleFromCurvature(curvature_left_per_m));
}

WheelSpeeds DiffDrivePlatform::FromSpeedAndCurvature(double speed_mps,
                                                     double curvature_left_per_m) const {
  const double w = speed_mps * curvature_left_per_m;
  WheelSpeeds s;
  s.left_radps = (speed_mps - 0.5 * w * track_m) / wheel_radius_m;
  s.right_radps = (speed_mps + 0.5 * w * track_m) / wheel_radius_m;
  const double peak = std::max(std::fabs(s.left_radps), std::fabs(s.right_radps));
  if (peak > max_wheel_speed_radps) {
    const double k = max_wheel_speed_radps / peak;
    s.left_radps *= k;
    s.right_radps *= k;
  }
  return s;
}

}  // namespace hil::estimator::guidance

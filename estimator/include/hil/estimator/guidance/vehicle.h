#pragma once
/// @file
/// What guidance knows of the vehicle: its pose in the local east-north plane and the two
/// platforms it can command — a front-steered vehicle (tractor, paper 003's push-rod robot:
/// curvature = tan δ / L at the rear axle) and a differential-drive base (curvature = ω / v at the
/// axle midpoint). Curvature is positive to the left (ENU, counter-clockwise).

#include <cstdint>
#include <optional>

#include <Eigen/Core>

namespace hil::estimator::guidance {

/// Pose of the guidance reference point: the rear axle's midpoint (front-steered) or the drive
/// axle's midpoint (differential drive).
struct VehiclePose2d {
  Eigen::Vector2d p_EN_m{0, 0};
  double yaw_rad = 0;  ///< direction of travel, ENU (0 = east, + counter-clockwise)
  double speed_mps = 0;
  /// The solution's time (ns; guidanced: the UTC time of day of its GGA), for trackers that
  /// need the interval between updates (FuzzyTracker's steering-rate limit); nullopt: unknown.
  std::optional<std::int64_t> t_ns;
};

struct FrontSteeredPlatform {
  double wheelbase_m = 2.5;
  double max_steer_rad = 0.6;
  /// δ = atan(κ L), clamped to ±max_steer_rad (δ > 0 = left).
  double SteerAngleFromCurvature(double curvature_left_per_m) const;
  double CurvatureFromSteerAngle(double steer_left_rad) const;
  /// κ of the nearest reachable steer angle.
  double Reachable(double curvature_left_per_m) const;
};

struct WheelSpeeds {
  double left_radps = 0, right_radps = 0;
};

struct DiffDrivePlatform {
  double track_m = 0.5;
  double wheel_radius_m = 0.1;
  double max_wheel_speed_radps = 20.0;
  /// v_R,L = v ± κ v track / 2 over the wheel radius; when a wheel would exceed its limit both are
  /// scaled down together, which keeps the curvature.
  WheelSpeeds FromSpeedAndCurvature(double speed_mps, double curvature_left_per_m) const;
};

}  // namespace hil::estimator::guidance

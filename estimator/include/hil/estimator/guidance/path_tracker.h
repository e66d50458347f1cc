#pragma once
/// @file
/// Path-tracking controllers: pure pursuit and Stanley. Each turns the vehicle's pose and the
/// planned path into a curvature command (1/m, + left); the platforms in vehicle.h turn it into a
/// steer angle or wheel speeds, and isobus_guidance_codec.h / the base protocol put it on the wire.
/// Both keep the previous projection as a search hint: one update costs a few edges of the path,
/// no allocation.
///
/// Pure pursuit (Coulter 1992): the goal is the path point `L_d` of arc length ahead of the
/// reference point's foot, L_d = clamp(lookahead_m + lookahead_gain_s·v, min, max); κ = 2 sin α /
/// D with α the goal's bearing from the heading and D its distance (paper 003's baseline: L_d = 2
/// m). Stanley (Hoffmann et al. 2007): at the front axle (a virtual one `wheelbase_m` ahead for a
/// differential-drive base), δ = ψ_e + atan(k·e_f / (k_soft + v)), κ = tan δ / L.

#include <cstddef>

#include "hil/estimator/guidance/planned_path.h"
#include "hil/estimator/guidance/vehicle.h"

namespace hil::estimator::guidance {

/// One controller answer.
struct TrackingCommand {
  double curvature_left_per_m = 0;
  double cross_track_m = 0;      ///< of the reference point, + = vehicle left of the path
  double heading_error_rad = 0;  ///< path direction minus vehicle yaw, wrapped to (−π, π]
  double s_m = 0;                ///< foot's arc length
  bool end_of_path = false;      ///< the foot reached the path's end: stop
};

struct PurePursuitConfig {
  double lookahead_m = 2.0;
  double lookahead_gain_s = 0.0;
  double min_lookahead_m = 0.5;
  double max_lookahead_m = 20.0;
  double search_window_m = 5.0;  ///< projection search around the previous foot
};

class PurePursuit {
 public:
  explicit PurePursuit(const PurePursuitConfig& config) : cfg_(config) {}
  TrackingCommand Update(const PlannedPath& path, const VehiclePose2d& pose);
  void Reset() { have_hint_ = false; }

 private:
  PurePursuitConfig cfg_;
  std::size_t hint_ = 0;
  bool have_hint_ = false;
};

struct StanleyConfig {
  double gain = 2.5;           ///< k (1/s)
  double softening_mps = 0.5;  ///< k_soft: keeps the gain finite at low speed
  double wheelbase_m = 2.5;    ///< front axle ahead of the reference point
  double max_steer_rad = 0.6;
  double search_window_m = 5.0;
};

class Stanley {
 public:
  explicit Stanley(const StanleyConfig& config) : cfg_(config) {}
  TrackingCommand Update(const PlannedPath& path, const VehiclePose2d& pose);
  void Reset() { have_hint_ = false; }

 private:
  StanleyConfig cfg_;
  std::size_t hint_ = 0;
  bool have_hint_ = false;
};

/// Angle wrapped to (−π, π].
double WrapPi(double a);

}  // namespace hil::estimator::guidance

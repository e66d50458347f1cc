#pragma once
/// @file
/// From the integrated horizontal motion to the full 3-D body motion: the vehicle stands on the
/// terrain (body z = surface normal, body x = the heading projected on the surface) and engine
/// vibration moves the body about its reference point. Everything is computed with Jet2, so
/// velocity/acceleration and angular rate/acceleration are the exact derivatives of position and
/// attitude.

#include <Eigen/Core>

#include "hil/truth/jet.h"
#include "hil/truth/terrain.h"
#include "hil/truth/vehicle.h"

namespace hil::truth {

/// The horizontal trajectory at one instant, with first and second time derivatives.
struct HorizontalJets {
  Jet2 e_m, n_m;  ///< ENU east, north of the reference point
  Jet2 yaw_rad;   ///< yaw of the body x axis, counter-clockwise from east
};

/// The body's motion relative to N at one instant.
struct BodyMotion {
  Eigen::Vector3d p_NB_N_m, v_NB_N_mps, a_NB_N_mps2;
  Eigen::Matrix3d R_NB;  ///< B → N
  Eigen::Vector3d w_NB_B_radps, alpha_NB_B_radps2;
};

/// Computes the body motion at time t_s (for the vibration phase).
BodyMotion CalcBodyMotion(const Terrain& terrain, const VibrationConfig& vibration,
                          const HorizontalJets& h, double t_s);

}  // namespace hil::truth

#pragma once
/// @file
/// Strapdown mechanization (a pure module): propagates the nominal navigation state one IMU
/// interval in the local tangent frame N (ENU, Earth-fixed, origin fixed), with a quaternion
/// attitude update.
///
///   q_NB(k+1) = Exp_N(−ω_IE·dt) ⊗ q_NB(k) ⊗ Exp_B(Δθ + coning)
///   v(k+1)    = v(k) + (I − ½[ζ×])·C_NB(k)·(Δv + ½Δθ×Δv + sculling) + (g_N − 2ω_IE×v)·dt, ζ =
///   ω_IE·dt p(k+1)    = p(k) + ½(v(k) + v(k+1))·dt
/// Coning and sculling use the previous interval's increments (two-sample, linear-rate assumption).
/// The flat tangent frame is exact for an Earth-fixed frame apart from gravity's direction, which
/// tilts by ~1.6e-4 rad per km from the origin; the filter re-anchors its origin far from it.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hil::estimator {

/// The nominal navigation state of the IMU (body) origin.
struct NavState {
  Eigen::Vector3d p_N_m = Eigen::Vector3d::Zero();           ///< position in N (ENU)
  Eigen::Vector3d v_N_mps = Eigen::Vector3d::Zero();         ///< velocity w.r.t. the Earth, in N
  Eigen::Quaterniond q_NB = Eigen::Quaterniond::Identity();  ///< body FLU → N
};

/// The Earth model the mechanization uses (constant near the origin).
struct EarthModel {
  Eigen::Vector3d g_N_mps2{0.0, 0.0, -9.80665};  ///< gravity (mass attraction + centrifugal)
  Eigen::Vector3d w_IE_N_radps = Eigen::Vector3d::Zero();  ///< Earth rate in N
  bool coriolis = true;                                    ///< apply −2ω_IE×v
};

/// Increments of the previous interval, for coning and sculling.
struct MechanizationMemory {
  Eigen::Vector3d prev_delta_angle_B_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d prev_delta_velocity_B_mps = Eigen::Vector3d::Zero();
  bool valid = false;
};

/// Rotation vector → unit quaternion.
Eigen::Quaterniond QuatFromRotationVector(const Eigen::Vector3d& phi_rad);
/// Skew-symmetric (cross-product) matrix.
Eigen::Matrix3d Skew(const Eigen::Vector3d& v);

/// Propagates `state` over one interval of `dt_s` with bias-compensated increments. Pure apart from
/// `memory`, which it reads and updates.
void Propagate(const EarthModel& earth, const Eigen::Vector3d& delta_angle_B_rad,
               const Eigen::Vector3d& delta_velocity_B_mps, double dt_s,
               MechanizationMemory& memory, NavState& state);

}  // namespace hil::estimator

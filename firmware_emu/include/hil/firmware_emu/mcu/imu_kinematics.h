#pragma once
/// @file
/// What an ideal IMU on the board measures, from the vehicle truth: the board sits at a lever arm
/// from the vehicle reference point (seed 000 put it at the end of a long tube), so it feels the
/// tangential (α × r) and centripetal (ω × (ω × r)) accelerations; its case frame I may be rotated
/// against the body frame B; the compass sees the local field plus the board's hard and soft iron.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "hil/firmware_emu/truth_sample.h"

namespace hil::mcu {

/// Where and how the board is mounted on the vehicle.
struct BoardMounting {
  Eigen::Vector3d p_BI_B_m = Eigen::Vector3d::Zero();        ///< lever arm, body FLU
  Eigen::Quaterniond q_BI = Eigen::Quaterniond::Identity();  ///< rotates I → B
};

/// The magnetic environment of the compass.
struct MagneticSpec {
  /// Local Earth field in ENU, µT (default: about Karaj, Iran: 28 µT north, 3 µT east, 40 µT down).
  Eigen::Vector3d field_N_uT{3.0, 28.0, -40.0};
  Eigen::Vector3d hard_iron_I_uT = Eigen::Vector3d::Zero();  ///< constant offset in I
  Eigen::Matrix3d soft_iron = Eigen::Matrix3d::Identity();   ///< multiplies the field in I
};

/// Ideal (error-free) sensor inputs in the IMU frame I.
struct IdealImu {
  Eigen::Vector3d f_I_mps2 = Eigen::Vector3d::Zero();   ///< specific force at the board
  Eigen::Vector3d w_I_radps = Eigen::Vector3d::Zero();  ///< inertial angular rate
  Eigen::Vector3d mag_I_uT = Eigen::Vector3d::Zero();   ///< field incl. hard and soft iron
};

/// Specific force at a point r (body frame) of a rigid body whose reference point feels f_B:
/// f_r = f_B + α × r + ω × (ω × r).
Eigen::Vector3d SpecificForceAtLeverArm(const Eigen::Vector3d& f_B_mps2,
                                        const Eigen::Vector3d& w_B_radps,
                                        const Eigen::Vector3d& alpha_B_radps2,
                                        const Eigen::Vector3d& r_B_m);

/// The ideal sensor inputs of a board mounted as `mount` on a vehicle in state `truth`.
IdealImu IdealImuFromTruth(const TruthSample& truth, const BoardMounting& mount,
                           const MagneticSpec& mag);

}  // namespace hil::mcu

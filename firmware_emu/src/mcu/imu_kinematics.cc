#include "hil/firmware_emu/mcu/imu_kinematics.h"

namespace hil::mcu {

Eigen::Vector3d SpecificForceAtLeverArm(const Eigen::Vector3d& f_B_mps2,
                                        const Eigen::Vector3d& w_B_radps,
                                        const Eigen::Vector3d& alpha_B_radps2,
                                        const Eigen::Vector3d& r_B_m) {
  return f_B_mps2 + alpha_B_radps2.cross(r_B_m) + w_B_radps.cross(w_B_radps.cross(r_B_m));
}

IdealImu IdealImuFromTruth(const TruthSample& truth, const BoardMounting& mount,
                           const MagneticSpec& mag) {
  const Eigen::Matrix3d R_IB = mount.q_BI.toRotationMatrix().transpose();
  // the lever-arm terms use the angular rate relative to the ground (Earth rate is negligible
  // at a lever arm of metres); the gyro measures the inertial rate
  const Eigen::Vector3d f_B = SpecificForceAtLeverArm(truth.f_B_mps2, truth.w_NB_B_radps,
                                                      truth.alpha_NB_B_radps2, mount.p_BI_B_m);
  IdealImu out;
  out.f_I_mps2 = R_IB * f_B;
  out.w_I_radps = R_IB * truth.w_IB_B_radps;
  const Eigen::Vector3d field_B = truth.q_NB.conjugate() * mag.field_N_uT;
  out.mag_I_uT = mag.soft_iron * (R_IB * field_B) + mag.hard_iron_I_uT;
  return out;
}

}  // namespace hil::mcu

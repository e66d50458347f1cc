// Wrong RTK fixes: control of the fixes of a suspect fix episode (RtkFixCheck). A wrong integer
// fix puts the receiver's position decimetres off by an offset that stays while the receiver holds
// the fix; its Doppler velocity does not depend on the ambiguities. The episode's fixes are fused
// less the offset its first fix showed against the filter (their increments, which the offset
// does not touch), with the offset's σ (that fix's and the filter's position σ then) added to
// theirs, and their velocities as usual. See estimator.md, "Wrong RTK fixes".
#include "hil/estimator/navigator.h"

namespace hil::estimator {

bool Navigator::RejectSuspectRtkFix(const GnssSample& g, const UpdateResult& r,
                                    const Eigen::Vector3d& p_antenna_N_m) {
  if (r.dof <= 0) return false;
  const bool suspect = rtk_check_.Observe(g.t, g.fix_quality, r.accepted, last_gnss_fused_t_);
  stats_.rtk_suspect_episodes = rtk_check_.suspect_episodes();
  stats_.rtk_suspect_fixes = rtk_check_.suspect_fixes();
  if (!suspect) return false;
  if (rtk_check_.suspect_began()) {
    // the update was rejected: the state is still the prediction the fix contradicts
    // its error: the fix's noise and the filter's own position error then (the latter is common
    // to every fix of the episode, so it is carried in their σ rather than averaged away)
    rtk_offset_N_m_ = p_antenna_N_m - ekf_.AntennaPosition();
    const Eigen::Vector3d pos_var = ekf_.covariance().diagonal().segment<3>(ekf_index::kPos);
    rtk_offset_std_m_ = (g.pos_std_enu_m.array().square() + pos_var.array().max(0.0)).sqrt();
  } else {
    // not in the innovation window, no fading: the receiver's error, not the filter's
    const Eigen::Vector3d std_m =
        (g.pos_std_enu_m.array().square() + rtk_offset_std_m_.array().square()).sqrt();
    ekf_.UpdatePosition(p_antenna_N_m - rtk_offset_N_m_, std_m);
  }
  step_.Remember(g.t, p_antenna_N_m, g.pos_std_enu_m, ekf_.AntennaPosition());
  return true;
}

}  // namespace hil::estimator

// GNSS velocity aid source of the navigator's EKF: control (the σ a fix velocity is fused with)
// here, fusion in ErrorStateEkf::UpdateVelocity. See estimator.md, "GNSS velocity noise".
#include <algorithm>
#include <chrono>
#include <cmath>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::FuseGnssVelocity(const GnssSample& g) {
  if (!g.has_velocity || !params_.use_gnss_velocity) return;
  Eigen::Vector3d std_mps = g.vel_std_enu_mps;
  // not on RTK fixes (GGA quality 4, 5): their position is already at centimetres, better than any
  // velocity integration makes it, and their NMEA velocity's error is then mostly its rounding
  // (RMC speed and course), constant along a straight row, which the increments cannot see
  // (wrong_rtk_fix: learned 0.010 m/s, horizontal NEES 3.96 -> 4.92; parked_for_hours: fused/raw
  // 1.1 -> 1.66)
  const bool rtk = g.fix_quality == 4 || g.fix_quality == 5;
  const bool learn = g.vel_std_configured && params_.gnss_vel_noise.enabled && !rtk;
  if (learn) {
    const double floor_mps = ekf_.params().gnss_vel_std_floor_mps;
    for (int i = 0; i < 2; ++i)
      std_mps[i] = vel_noise_.Std(g.vel_std_enu_mps[i], g.hdop, floor_mps);
    // the fix's velocity increment against the INS's own (unaided) over the same interval: 2 R
    // and the INS increment's error, which errs on the safe side, whatever the process noise says
    const Eigen::Vector3d lever_N = ekf_.AntennaVelocity() - ekf_.state().v_N_mps;
    if (last_vel_fix_t_ && g.t - *last_vel_fix_t_ <= params_.robust.gap_after) {
      const Eigen::Vector3d d =
          (g.vel_enu_mps - last_vel_fix_) - (ins_dv_N_mps_ + lever_N - last_vel_lever_N_);
      vel_noise_.AddIncrement(d.x(), d.y(), std::max(g.vel_std_enu_mps.x(), g.vel_std_enu_mps.y()),
                              g.hdop);
      if (last_vel_d_)
        vel_noise_.AddIncrementLag(d.x(), d.y(), last_vel_d_->x(), last_vel_d_->y(),
                                   std::max(g.vel_std_enu_mps.x(), g.vel_std_enu_mps.y()));
      last_vel_d_ = d.head<2>();
    } else {
      last_vel_d_.reset();  // a gap: the next increment has no neighbour
    }
    last_vel_fix_t_ = g.t;
    last_vel_fix_ = g.vel_enu_mps;
    last_vel_lever_N_ = lever_N;
    ins_dv_N_mps_.setZero();
  }
  // the INS's ripple at this instant, as the previous fixes saw it too: not a velocity error
  const Eigen::Vector3d ripple_N_mps =
      params_.fix_velocity_ripple
          ? fix_ripple_.Ripple_N_mps(
                std::chrono::duration<double>(params_.robust.gap_after).count())
          : Eigen::Vector3d::Zero();
  fix_ripple_.Restart();
  const UpdateResult rv = ekf_.UpdateVelocity(g.vel_enu_mps + ripple_N_mps, std_mps);
  stats_.gnss_vel_std_mps = std::max(std_mps.x(), std_mps.y());
  stats_.gnss_vel_std_learned = learn && std_mps.x() < g.vel_std_enu_mps.x();
  Record(kAidGnssVelocity, rv);
  stats_.last_nis_vel = rv.nis;
}

}  // namespace hil::estimator

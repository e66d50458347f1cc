// GNSS step check: a fix's increment against the INS displacement (gnss_step_check.h).
#include "hil/estimator/gnss_step_check.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace hil::estimator {

bool GnssStepCheck::IsStep(GpsTime t, const Eigen::Vector3d& p_fix_N_m,
                           const Eigen::Vector3d& fix_std_m, const Eigen::Vector3d& p_ins_N_m,
                           const Eigen::Vector3d& vel_var_N_m2ps2) {
  if (!prev_t_ || t <= *prev_t_ || t - *prev_t_ > params_.max_interval) return false;
  if (!p_fix_N_m.allFinite() || !p_ins_N_m.allFinite()) return false;
  const double dt_s = std::chrono::duration<double>(t - *prev_t_).count();
  const Eigen::Vector3d d = (p_fix_N_m - prev_fix_) - (p_ins_N_m - prev_ins_);
  const Eigen::Vector3d var = fix_std_m.array().square() + prev_std_.array().square() +
                              vel_var_N_m2ps2.array().max(0.0) * dt_s * dt_s;
  const double sigma_d = std::sqrt(var.maxCoeff());
  last_step_m_ = d.norm();
  return last_step_m_ > std::max(params_.min_step_m, params_.gate_sigma * sigma_d);
}

void GnssStepCheck::Remember(GpsTime t, const Eigen::Vector3d& p_fix_N_m,
                             const Eigen::Vector3d& fix_std_m,
                             const Eigen::Vector3d& p_ins_after_N_m) {
  prev_t_ = t;
  prev_fix_ = p_fix_N_m;
  prev_std_ = fix_std_m;
  prev_ins_ = p_ins_after_N_m;
}

}  // namespace hil::estimator

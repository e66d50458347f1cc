#include "hil/estimator/imu_usability_check.h"

#include <algorithm>
#include <cmath>

namespace hil::estimator {
namespace {

// Wilson–Hilferty: χ²_p(k) ≈ k (1 − 2/(9k) + z_p √(2/(9k)))³
double WilsonHilfertyQuantile(int dof, double z) {
  if (dof <= 0) return 0.0;
  const double k = static_cast<double>(dof);
  const double a = 2.0 / (9.0 * k);
  const double c = 1.0 - a + z * std::sqrt(a);
  return k * std::max(0.0, c * c * c);
}

double WindowSeconds(Nanoseconds d) { return static_cast<double>(d.count()) * 1e-9; }

}  // namespace

double ImuUsabilityCheck::enter_threshold() const {
  return WilsonHilfertyQuantile(dof(), p_.enter_z);
}
double ImuUsabilityCheck::leave_threshold() const {
  return WilsonHilfertyQuantile(dof(), p_.leave_z);
}

void ImuUsabilityCheck::AddImu(const Eigen::Vector3d& delta_angle_B_rad,
                               const Eigen::Vector3d& delta_velocity_B_mps, double dt_s) {
  const Eigen::Vector3d& dtheta = delta_angle_B_rad;
  const Eigen::Vector3d& dv = delta_velocity_B_mps;
  const double dt = dt_s;
  if (!p_.enabled || !start_t_ || !(dt > 0) || !dtheta.allFinite() || !dv.allFinite()) return;
  // the increment in the window's first body frame (rotation to the interval's middle)
  const double angle = dtheta.norm();
  const Eigen::Quaterniond half =
      angle > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * angle, dtheta / angle))
                : Eigen::Quaterniond::Identity();
  const Eigen::Vector3d dv0 = (q_B0_B_ * half) * dv;
  q_B0_B_ = (q_B0_B_ * half * half).normalized();
  dv_B0_ += dv0;
  T_ += dt;
  block_dv_ += dv0;
  block_T_ += dt;
  if (block_T_ >= p_.block_s - 1e-6) {
    if (n_blocks_ < kMaxBlocks) blocks_[n_blocks_++] = block_dv_ / block_T_;
    block_dv_.setZero();
    block_T_ = 0;
  }
}

void ImuUsabilityCheck::StartWindow(GpsTime t, const Eigen::Vector3d& v_N_mps,
                                    const Eigen::Vector3d& std_mps) {
  start_t_ = t;
  v_start_ = v_N_mps;
  std_start_ = std_mps;
  q_B0_B_ = Eigen::Quaterniond::Identity();
  dv_B0_.setZero();
  block_dv_.setZero();
  T_ = block_T_ = 0;
  n_blocks_ = 0;
}

bool ImuUsabilityCheck::AddGnssVelocity(GpsTime t, const Eigen::Vector3d& v_N_mps,
                                        const Eigen::Vector3d& std_mps,
                                        const Eigen::Vector3d& g_N_mps2) {
  if (!p_.enabled || !v_N_mps.allFinite() || !std_mps.allFinite()) return false;
  const bool gap =
      !last_fix_t_ || WindowSeconds(t - *last_fix_t_) > p_.max_fix_gap_s || t <= *last_fix_t_;
  last_fix_t_ = t;
  if (gap || !start_t_) {
    StartWindow(t, v_N_mps, std_mps);
    return false;
  }
  const double span = WindowSeconds(t - *start_t_);
  if (span < p_.window_s - 1e-3) return false;
  bool tested = false;
  // the IMU must have covered the window (not a window the IMU fell silent in)
  if (T_ > 0.9 * span && n_blocks_ >= 3) {
    CloseWindow(span, v_N_mps, std_mps, g_N_mps2);
    tested = count_ >= std::max(2, p_.min_windows);
    if (tested) Test();
  }
  StartWindow(t, v_N_mps, std_mps);
  return tested;
}

void ImuUsabilityCheck::CloseWindow(double span_s, const Eigen::Vector3d& v_N_mps,
                                    const Eigen::Vector3d& std_mps,
                                    const Eigen::Vector3d& g_N_mps2) {
  const Eigen::Vector3d f_imu = dv_B0_ / T_;
  const Eigen::Vector3d f_gnss = (v_N_mps - v_start_) / span_s - g_N_mps2;
  const Eigen::Vector3d u = f_imu.normalized(), w = f_gnss.normalized();
  // batch means: the scatter of the blocks' means along the mean's direction, over their number
  double mean = 0;
  for (int i = 0; i < n_blocks_; ++i) mean += u.dot(blocks_[i]) / n_blocks_;
  double ss = 0;
  for (int i = 0; i < n_blocks_; ++i) ss += std::pow(u.dot(blocks_[i]) - mean, 2);
  const double var_imu =
      std::max(ss / (n_blocks_ - 1) / n_blocks_, accel_noise_ * accel_noise_ / T_);
  const Eigen::Vector3d var_v = std_mps.cwiseAbs2() + std_start_.cwiseAbs2();
  const double var_gnss = w.cwiseAbs2().dot(var_v) / (span_s * span_s);
  m_[next_] = f_imu.norm() - f_gnss.norm();
  var_[next_] = var_imu + var_gnss;
  last_m_ = m_[next_];
  last_std_ = std::sqrt(var_[next_]);
  const int cap = std::min(p_.windows, kMaxWindows);
  next_ = (next_ + 1) % cap;
  count_ = std::min(count_ + 1, cap);
}

void ImuUsabilityCheck::Test() {
  const int k = count_;  // the ring holds the last min(seen, K) windows
  dof_ = k - 1;
  // the bias random walk over the test's span: the scatter of its samples about their mean
  const double rw_var = bias_rw_ * bias_rw_ * k * p_.window_s / 6.0;
  double sw = 0, swm = 0;
  for (int i = 0; i < k; ++i) {
    const double w = 1.0 / (var_[i] + rw_var);
    sw += w;
    swm += w * m_[i];
  }
  const double mean = swm / sw;
  double lambda = 0;
  for (int i = 0; i < k; ++i) lambda += std::pow(m_[i] - mean, 2) / (var_[i] + rw_var);
  statistic_ = lambda;
  ++tests_;
  if (!unusable_ && lambda > enter_threshold()) {
    unusable_ = true;
    passes_ = 0;
    ++periods_;
  } else if (unusable_) {
    passes_ = lambda < leave_threshold() ? passes_ + 1 : 0;
    if (passes_ >= p_.leave_tests) unusable_ = false;
  }
}

}  // namespace hil::estimator

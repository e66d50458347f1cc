#include "hil/estimator/vehicle_model_filter.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace hil::estimator {
namespace {

constexpr int kVmP = 0, kVmPsi = 2, kVmV = 3, kVmW = 4, kVmE = 5;
constexpr double kVmMaxStepS = 0.1;  // the model's integration step

double ModelSeconds(Nanoseconds d) { return static_cast<double>(d.count()) * 1e-9; }

// R(ψ)·l and its derivative by ψ (horizontal lever arm)
Eigen::Vector2d LeverRotated(double psi, const Eigen::Vector3d& l) {
  const double c = std::cos(psi), s = std::sin(psi);
  return {c * l.x() - s * l.y(), s * l.x() + c * l.y()};
}
Eigen::Vector2d LeverRotatedDerivative(double psi, const Eigen::Vector3d& l) {
  const double c = std::cos(psi), s = std::sin(psi);
  return {-s * l.x() - c * l.y(), c * l.x() - s * l.y()};
}

}  // namespace

double VehicleModelFilter::GnssErrorStd(double hdop) const {
  if (p_.gnss_error_tau_s <= 0) return 0.0;
  return p_.gnss_error_std_m * (hdop > 0 ? std::clamp(hdop, 0.5, 20.0) : 1.0);
}

void VehicleModelFilter::Start(GpsTime t, const Eigen::Vector3d& p_antenna_N_m,
                               const Eigen::Vector3d& pos_std_m,
                               const Eigen::Vector3d& v_antenna_N_mps,
                               const Eigen::Vector3d& vel_std_mps, double hdop) {
  const double speed = v_antenna_N_mps.head<2>().norm();
  const double psi = std::atan2(v_antenna_N_mps.y(), v_antenna_N_mps.x());
  const double se = GnssErrorStd(hdop);
  x_.setZero();
  x_.segment<2>(kVmP) = p_antenna_N_m.head<2>() - LeverRotated(psi, p_.lever_arm_B_m);
  x_(kVmPsi) = psi;
  x_(kVmV) = speed;
  P_.setZero();
  for (int i = 0; i < 2; ++i) {
    P_(kVmP + i, kVmP + i) = pos_std_m[i] * pos_std_m[i] + se * se;
    P_(kVmE + i, kVmE + i) = se * se;
    P_(kVmP + i, kVmE + i) = P_(kVmE + i, kVmP + i) = -se * se;  // p = p_antenna − e
  }
  const double course_std = vel_std_mps.head<2>().maxCoeff() / speed;
  P_(kVmPsi, kVmPsi) = course_std * course_std + 0.05 * 0.05;  // + side slip (ours: 3°)
  P_(kVmV, kVmV) = vel_std_mps.head<2>().squaredNorm();
  P_(kVmW, kVmW) = 0.05 * 0.05;  // ours: a turn of 3 °/s unseen at the start
  t_ = t;
  ready_ = true;
  consecutive_rejected_ = 0;
}

void VehicleModelFilter::Step(double dt_s, Vector& x, Matrix& P) const {
  const double dt = dt_s;
  const double psi_m = x(kVmPsi) + 0.5 * x(kVmW) * dt;
  const double c = std::cos(psi_m), s = std::sin(psi_m), v = x(kVmV);
  const double decay = p_.gnss_error_tau_s > 0 ? std::exp(-dt / p_.gnss_error_tau_s) : 0.0;
  Matrix F = Matrix::Identity();
  F(kVmP, kVmPsi) = -v * dt * s;
  F(kVmP, kVmV) = dt * c;
  F(kVmP, kVmW) = -v * dt * s * 0.5 * dt;
  F(kVmP + 1, kVmPsi) = v * dt * c;
  F(kVmP + 1, kVmV) = dt * s;
  F(kVmP + 1, kVmW) = v * dt * c * 0.5 * dt;
  F(kVmPsi, kVmW) = dt;
  F(kVmE, kVmE) = F(kVmE + 1, kVmE + 1) = decay;
  x(kVmP) += v * dt * c;
  x(kVmP + 1) += v * dt * s;
  x(kVmPsi) = std::remainder(x(kVmPsi) + x(kVmW) * dt, 2.0 * M_PI);
  x.segment<2>(kVmE) *= decay;
  P = F * P * F.transpose();
  const double qp = p_.position_rw_m_rthz * p_.position_rw_m_rthz * dt;
  P(kVmP, kVmP) += qp;
  P(kVmP + 1, kVmP + 1) += qp;
  P(kVmV, kVmV) += p_.speed_rw_mps_rthz * p_.speed_rw_mps_rthz * dt;
  P(kVmW, kVmW) += p_.yaw_rate_rw_radps_rthz * p_.yaw_rate_rw_radps_rthz * dt;
  const double se = gnss_error_std_m_;  // the stationary σ at the last fix's HDOP
  P(kVmE, kVmE) += se * se * (1.0 - decay * decay);
  P(kVmE + 1, kVmE + 1) += se * se * (1.0 - decay * decay);
}

void VehicleModelFilter::PredictTo(GpsTime t, Vector& x, Matrix& P) const {
  x = x_;
  P = P_;
  double left = ModelSeconds(t - t_);
  while (left > 1e-9) {
    const double dt = std::min(left, kVmMaxStepS);
    Step(dt, x, P);
    left -= dt;
  }
}

template <int M>
bool VehicleModelFilter::Update(const Eigen::Matrix<double, M, 1>& nu,
                                const Eigen::Matrix<double, M, 7>& H,
                                const Eigen::Matrix<double, M, M>& R, bool gated) {
  const Eigen::Matrix<double, M, M> S = H * P_ * H.transpose() + R;
  const Eigen::Matrix<double, M, M> S_inv = S.inverse();
  const double nis = nu.dot(S_inv * nu);
  if (!std::isfinite(nis)) return false;
  if (gated && nis > p_.gate_sigma * p_.gate_sigma * M) return false;
  const Eigen::Matrix<double, 7, M> K = P_ * H.transpose() * S_inv;
  x_ += K * nu;
  x_(kVmPsi) = std::remainder(x_(kVmPsi), 2.0 * M_PI);
  const Matrix IKH = Matrix::Identity() - K * H;
  P_ = IKH * P_ * IKH.transpose() + K * R * K.transpose();  // Joseph form
  P_ = 0.5 * (P_ + P_.transpose()).eval();
  return true;
}

bool VehicleModelFilter::AddFix(GpsTime t, const Eigen::Vector3d& p_antenna_N_m,
                                const Eigen::Vector3d& pos_std_m, bool has_velocity,
                                const Eigen::Vector3d& v_antenna_N_mps,
                                const Eigen::Vector3d& vel_std_mps, double hdop) {
  if (!p_antenna_N_m.allFinite() || !pos_std_m.allFinite() || (ready_ && t <= t_)) return false;
  height_m_ = p_antenna_N_m.z() - p_.lever_arm_B_m.z();
  gnss_error_std_m_ = GnssErrorStd(hdop);
  // the fix's white σ and the receiver's correlated error in height (the EKF's model, by HDOP)
  const double dop = hdop > 0 ? std::clamp(hdop, 0.5, 20.0) : 1.0;
  height_std_m_ = std::hypot(pos_std_m.z(), p_.gnss_error_vertical_std_m * dop);
  const bool has_course = has_velocity && v_antenna_N_mps.allFinite() && vel_std_mps.allFinite() &&
                          v_antenna_N_mps.head<2>().norm() >= p_.min_speed_mps;
  if (!ready_) {
    if (has_course) Start(t, p_antenna_N_m, pos_std_m, v_antenna_N_mps, vel_std_mps, hdop);
    return ready_;
  }
  PredictTo(t, x_, P_);
  t_ = t;
  const double psi = x_(kVmPsi);
  Eigen::Matrix<double, 2, 7> H = Eigen::Matrix<double, 2, 7>::Zero();
  H.block<2, 2>(0, kVmP).setIdentity();
  H.col(kVmPsi) = LeverRotatedDerivative(psi, p_.lever_arm_B_m);
  H.block<2, 2>(0, kVmE).setIdentity();
  const Eigen::Vector2d nu = p_antenna_N_m.head<2>() - x_.segment<2>(kVmP) -
                             LeverRotated(psi, p_.lever_arm_B_m) - x_.segment<2>(kVmE);
  const Eigen::Matrix2d R = pos_std_m.head<2>().cwiseAbs2().asDiagonal();
  const bool taken = Update<2>(nu, H, R, true);
  if (!taken) {
    ++rejected_;
    if (++consecutive_rejected_ >= p_.restart_after && has_course) {
      Start(t, p_antenna_N_m, pos_std_m, v_antenna_N_mps, vel_std_mps, hdop);
      ++restarts_;
    }
    return false;
  }
  consecutive_rejected_ = 0;
  if (has_velocity && v_antenna_N_mps.allFinite() && vel_std_mps.allFinite()) {
    const double c = std::cos(x_(kVmPsi)), s = std::sin(x_(kVmPsi)), v = x_(kVmV), w = x_(kVmW);
    const Eigen::Vector2d r1 = LeverRotatedDerivative(x_(kVmPsi), p_.lever_arm_B_m);
    const Eigen::Vector2d r0 = LeverRotated(x_(kVmPsi), p_.lever_arm_B_m);
    Eigen::Matrix<double, 2, 7> Hv = Eigen::Matrix<double, 2, 7>::Zero();
    Hv.col(kVmPsi) = Eigen::Vector2d(-v * s, v * c) - w * r0;
    Hv.col(kVmV) = Eigen::Vector2d(c, s);
    Hv.col(kVmW) = r1;
    const Eigen::Vector2d nuv = v_antenna_N_mps.head<2>() - (v * Eigen::Vector2d(c, s) + w * r1);
    const Eigen::Matrix2d Rv = vel_std_mps.head<2>().cwiseAbs2().asDiagonal();
    Update<2>(nuv, Hv, Rv, true);
  }
  return true;
}

}  // namespace hil::estimator

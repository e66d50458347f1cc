// Is the IMU usable at all? The accelerometer against the GNSS (ImuUsabilityCheck), and the
// GNSS + vehicle-model solution while it is not (VehicleModelFilter). estimator.md, "An IMU that
// cannot be used".
#include <algorithm>
#include <cmath>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

VehicleModelParams FallbackVehicleParams(const NavigatorParams& p) {
  VehicleModelParams v = p.fallback_vehicle;
  v.lever_arm_B_m = p.ekf.lever_arm_B_m;
  v.gnss_error_tau_s = p.ekf.gnss_error_tau_s;
  v.gnss_error_std_m = p.ekf.gnss_error_std_m;
  v.gnss_error_vertical_std_m = p.ekf.gnss_error_vertical_std_m > 0
                                    ? p.ekf.gnss_error_vertical_std_m
                                    : p.ekf.gnss_error_std_m;
  // the user said the vehicle holds its speed (the EKF's speed model): so does the fallback
  if (p.ekf.speed_rw_mps_rthz > 0) v.speed_rw_mps_rthz = p.ekf.speed_rw_mps_rthz;
  v.min_speed_mps = p.align_min_speed_mps;
  v.gate_sigma = p.ekf.gate_sigma;
  return v;
}

void Navigator::ObserveImuUsability(const ImuSample& s) {
  if (params_.mode != NavMode::kEkf || !params_.imu_usability.enabled) return;
  imu_check_.AddImu(s.delta_angle_B_rad - ekf_.gyro_bias() * s.dt_s, s.delta_velocity_B_mps,
                    s.dt_s);
}

void Navigator::ControlImuUsability(const GnssSample& g, const Eigen::Vector3d& p_antenna_N_m) {
  if (params_.mode != NavMode::kEkf || !params_.imu_usability.enabled) return;
  fallback_.AddFix(g.t, p_antenna_N_m, g.pos_std_enu_m, g.has_velocity, g.vel_enu_mps,
                   g.vel_std_enu_mps, g.hdop);
  if (!g.has_velocity) return;
  if (!imu_check_.AddGnssVelocity(g.t, g.vel_enu_mps, g.vel_std_enu_mps, ekf_.earth().g_N_mps2))
    return;
  stats_.imu_unusable = imu_check_.unusable();
  stats_.imu_consistency_stat = imu_check_.statistic();
  stats_.imu_consistency_threshold = imu_check_.enter_threshold();
  stats_.imu_consistency_tests = imu_check_.tests();
  stats_.imu_unusable_periods = imu_check_.unusable_periods();
}

NavOutput Navigator::VehicleModelOutput() const {
  NavOutput o;
  o.status = status_ | kStatusImuUnusable | (ekf_.repairs() > 0 ? kStatusCovarianceRepaired : 0u);
  o.valid = true;
  o.t = std::max(newest_imu_t_, fallback_.time());
  VehicleModelFilter::Vector x;
  VehicleModelFilter::Matrix P;
  fallback_.PredictTo(o.t, x, P);
  const double psi = x(2), v = x(3);
  o.p_N_m << x(0), x(1), fallback_.height_m();  // the last fix's height, local frame
  o.v_N_mps << v * std::cos(psi), v * std::sin(psi), 0.0;
  o.q_NB = Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ());
  o.has_attitude = true;
  o.position = frame_.ToLla(o.p_N_m);
  o.pos_std_enu_m << std::sqrt(P(0, 0)), std::sqrt(P(1, 1)),
      std::hypot(fallback_.height_std_m(), std::sqrt(height_datum_var_m2_));
  // velocity along the heading: σ of v along it, v·σψ across it (rotated into E, N)
  const double c = std::cos(psi), s = std::sin(psi);
  const double along = P(3, 3), across = v * v * P(2, 2);
  o.vel_std_enu_mps << std::sqrt(c * c * along + s * s * across),
      std::sqrt(s * s * along + c * c * across), 0.0;
  // roll and pitch are not estimated: their σ is the EKF's, the heading's the model's
  const EkfMatrix& Pe = ekf_.covariance();
  o.att_std_rad << std::sqrt(Pe(ekf_index::kAtt, ekf_index::kAtt)),
      std::sqrt(Pe(ekf_index::kAtt + 1, ekf_index::kAtt + 1)), std::sqrt(P(2, 2));
  o.accel_bias_B = ekf_.accel_bias();
  o.gyro_bias_B = ekf_.gyro_bias();
  return o;
}

}  // namespace hil::estimator

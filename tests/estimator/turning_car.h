// A test car for the EKF's gyro-triad and time-base states: it drives straight rows with 180°
// headland turns between them, alternately left and right (a boustrophedon), on 10 Hz RTK-class
// fixes (white σ 1 cm, 5 cm/s) and the NHC. Its IMU can have the x and y gyros coupled to the z
// rate (the x gyro reads ω_x + m_xz·ω_z), the accelerometer's errors in the lateral force (the y
// accelerometer reads (1 + k_ay)·f_y, the x and z accelerometers see m_xy·f_y and m_zy·f_y) and
// its samples tagged late by whole IMU intervals.
#pragma once

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <random>

#include "hil/estimator/error_state_ekf.h"

namespace hil::estimator::test {

struct TurningCarSpec {
  double coupling_x_rad = 0.0;     ///< m_xz: the x gyro's coupling to the z rate
  double coupling_y_rad = 0.0;     ///< m_yz
  double accel_scale_y = 0.0;      ///< k_ay: the y accelerometer's scale error
  double accel_coupling_xy = 0.0;  ///< m_xy: the x accelerometer's coupling to f_y (rad)
  double accel_coupling_zy = 0.0;  ///< m_zy: the z accelerometer's coupling to f_y (rad)
  int lag_samples = 0;             ///< IMU samples tagged this many intervals late
  double speed_mps = 5.0;
  double turn_rate_radps = 0.3;  ///< a U-turn of π at 0.3 rad/s: 10.5 s
  double row_s = 40.0;           ///< a row: 40 s
  /// the yaw rate's ramp into and out of a turn (s; 0: a step), the turn lengthened by it so that
  /// it still turns π (a car's steering takes a second or so)
  double turn_ramp_s = 0.0;
  std::uint64_t seed = 2026;
};

class TurningCar {
 public:
  static constexpr double kDt = 0.01;  // IMU interval (100 Hz)

  TurningCar(const TurningCarSpec& spec, const EkfParams& filter) : spec_(spec), rng_(spec.seed) {
    ekf_ = ErrorStateEkf(filter, EarthModel{});
    NavState s;
    s.v_N_mps = VelocityN();
    s.q_NB = Attitude();
    ekf_.Initialize(s);
  }
  /// The car's filter parameters as navd's car configuration has them
  /// (field_realism/imu_time_tag_lag.yaml), every optional state off.
  static EkfParams CarFilter() {
    EkfParams p;
    p.accel_noise_mps2_rthz = 0.01;
    p.gyro_noise_radps_rthz = 5e-4;
    p.nhc_std_mps = 0.05;
    p.gnss_error_tau_s = 30.0;
    p.gnss_error_std_m = 0.008;
    p.gyro_scale_z_std = 0.0;
    p.gyro_z_coupling_x_std_rad = p.gyro_z_coupling_y_std_rad = 0.0;
    p.accel_y_force_std = 0.0;
    p.imu_time_residual_std_s = 0.0;
    return p;
  }
  double Period_s() const { return spec_.row_s + TurnDuration_s(); }

  /// Runs to t_end_s; adds the tilt error of every 100 ms in [after_s, t_end_s) to its sum.
  void RunTo(double t_end_s, double after_s) {
    while (t_ + 0.5 * kDt < t_end_s) {
      Step();
      if (++k_ % 10 != 0) continue;
      ekf_.UpdateNonHolonomic();
      const Eigen::Vector3d n_p(n_(rng_), n_(rng_), n_(rng_));
      const Eigen::Vector3d n_v(n_(rng_), n_(rng_), n_(rng_));
      ekf_.UpdatePosition(p_N_m_ + 0.01 * n_p, Eigen::Vector3d::Constant(0.01));
      ekf_.UpdateVelocity(VelocityN() + 0.05 * n_v, Eigen::Vector3d::Constant(0.05));
      if (t_ < after_s) continue;
      const Eigen::AngleAxisd att_error(ekf_.state().q_NB * Attitude().inverse());
      const Eigen::Vector3d phi_N = att_error.angle() * att_error.axis();
      tilt_sq_sum_rad2_ += phi_N.head<2>().squaredNorm();
      ++samples_;
    }
  }
  double RmsTilt_deg() const { return Rms(tilt_sq_sum_rad2_) * 180.0 / std::numbers::pi; }
  const ErrorStateEkf& ekf() const { return ekf_; }

 private:
  double Rms(double sum) const {
    return samples_ > 0 ? std::sqrt(sum / static_cast<double>(samples_)) : 0.0;
  }
  double TurnDuration_s() const {
    return std::numbers::pi / spec_.turn_rate_radps + spec_.turn_ramp_s;
  }
  // The yaw rate at t: rows, then U-turns, left and right in turn (ENU, counter-clockwise > 0),
  // ramped in and out over turn_ramp_s.
  double YawRate(double t_s) const {
    const double period = Period_s();
    const double in_turn_s = std::fmod(t_s, period) - spec_.row_s;
    if (in_turn_s < 0.0) return 0.0;
    const bool left = static_cast<long>(std::floor(t_s / period)) % 2 == 0;
    const double edge_s = std::min(in_turn_s, TurnDuration_s() - in_turn_s);
    const double ramp = spec_.turn_ramp_s > 0 ? std::min(1.0, edge_s / spec_.turn_ramp_s) : 1.0;
    return (left ? spec_.turn_rate_radps : -spec_.turn_rate_radps) * ramp;
  }
  Eigen::Quaterniond Attitude() const {
    return Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad_, Eigen::Vector3d::UnitZ()));
  }
  Eigen::Vector3d VelocityN() const { return Attitude() * Eigen::Vector3d(spec_.speed_mps, 0, 0); }
  // The EKF's gravity at a position (mechanization.cc: plumb line tilting away from the origin).
  static Eigen::Vector3d Gravity(const Eigen::Vector3d& p) {
    const double g = 9.80665, r = 6371000.0;
    return Eigen::Vector3d(-g * p.x() / r, -g * p.y() / r, -g + 2.0 * g * p.z() / r);
  }
  // One IMU interval: the increments at the interval's middle (the gyro's couplings applied, the
  // sample queued for its late tag), then the truth advanced.
  void Step() {
    const double w = YawRate(t_ + 0.5 * kDt);
    const Eigen::AngleAxisd C_mid(yaw_rad_ + 0.5 * w * kDt, Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d v_mid = C_mid * Eigen::Vector3d(spec_.speed_mps, 0, 0);
    const Eigen::Vector3d a_N = C_mid * Eigen::Vector3d(0, spec_.speed_mps * w, 0);
    Eigen::Vector3d f_B = C_mid.inverse() * (a_N - Gravity(p_N_m_ + 0.5 * kDt * v_mid));
    f_B += Eigen::Vector3d(spec_.accel_coupling_xy, spec_.accel_scale_y, spec_.accel_coupling_zy) *
           f_B.y();
    const Eigen::Vector3d w_B(spec_.coupling_x_rad * w, spec_.coupling_y_rad * w, w);
    const Eigen::Vector3d n_g(n_(rng_), n_(rng_), n_(rng_)), n_a(n_(rng_), n_(rng_), n_(rng_));
    queue_.push_back(
        {w_B * kDt + 5e-4 * std::sqrt(kDt) * n_g, f_B * kDt + 0.01 * std::sqrt(kDt) * n_a});
    // a late tag: the interval's increments arrive with a later interval's time
    const Sample s = queue_.front();
    if (static_cast<int>(queue_.size()) > spec_.lag_samples) queue_.pop_front();
    ekf_.Predict(s.dth, s.dv, kDt);
    p_N_m_ += v_mid * kDt;
    yaw_rad_ += w * kDt;
    t_ += kDt;
  }

  struct Sample {
    Eigen::Vector3d dth, dv;
  };
  TurningCarSpec spec_;
  ErrorStateEkf ekf_;
  std::deque<Sample> queue_;
  Eigen::Vector3d p_N_m_ = Eigen::Vector3d::Zero();
  double yaw_rad_ = 0.0;
  double t_ = 0.0;
  long k_ = 0;
  double tilt_sq_sum_rad2_ = 0.0;
  long samples_ = 0;
  std::mt19937_64 rng_;
  std::normal_distribution<double> n_{0.0, 1.0};
};

}  // namespace hil::estimator::test

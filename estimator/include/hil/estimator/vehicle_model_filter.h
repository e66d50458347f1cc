#pragma once
/// @file
/// GNSS + ground-vehicle model: the solution when the IMU cannot be used (estimator.md, "An IMU
/// that cannot be used"). A Kalman filter (extended: the heading enters non-linearly) on
/// x = [p_E, p_N, ψ, v, ω, e_E, e_N]: the body reference point's horizontal position, its heading
/// (body x, radians counter-clockwise from east), forward speed and yaw rate, and the receiver's
/// correlated position error (first-order Gauss–Markov, the EKF's model).
/// Motion: constant turn rate and velocity (CTRV) with the non-holonomic constraint built in (the
/// body moves along its heading): ṗ = v·(cos ψ, sin ψ), ψ̇ = ω, v̇ and ω̇ white (random walks of
/// `speed_rw_mps_rthz`, `yaw_rate_rw_radps_rthz`), plus a white position diffusion
/// `position_rw_m_rthz` for slip and the speed's short deviations; ė = −e/τ + w.
/// Measurements: the antenna's position p + R(ψ)·l_xy + e and velocity v·(cos ψ, sin ψ) +
/// ω·R(ψ)·(−l_y, l_x) (Rong Li and Jilkov, "Survey of maneuvering target tracking. Part I:
/// dynamic models", IEEE Trans. AES 39(4), 2003, for CTRV). Height: the last fix's, less the
/// lever arm's height, with its σ and the correlated error's in height. χ²-gated at `gate_sigma`;
/// `restart_after` rejected fixes in a row restart it at the fix. Fixed size, no allocation.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/time_types.h"

namespace hil::estimator {

struct VehicleModelParams {
  double speed_rw_mps_rthz = 0.05;       ///< forward speed random walk (ours: a vehicle's throttle)
  double yaw_rate_rw_radps_rthz = 0.02;  ///< yaw-rate random walk (ours: a turn begun in ~5 s)
  double position_rw_m_rthz = 0.02;      ///< white position diffusion (ours: slip, speed ripple)
  double gnss_error_tau_s = 0.0;         ///< correlated GNSS error τ (0: white fixes only)
  double gnss_error_std_m = 0.0;         ///< its σ per horizontal axis at HDOP 1
  double gnss_error_vertical_std_m = 0.0;  ///< its σ in height at HDOP 1 (in the height's σ)
  double min_speed_mps = 0.2;              ///< a course is a heading above this speed
  double gate_sigma = 5.0;
  int restart_after = 5;
  Eigen::Vector3d lever_arm_B_m = Eigen::Vector3d::Zero();  ///< GNSS antenna in the body frame
};

class VehicleModelFilter {
 public:
  using Vector = Eigen::Matrix<double, 7, 1>;
  using Matrix = Eigen::Matrix<double, 7, 7>;

  VehicleModelFilter() = default;
  explicit VehicleModelFilter(const VehicleModelParams& p) : p_(p) {}

  /// One GNSS fix (antenna, local N frame) with its σ; the velocity when `has_velocity`; the
  /// receiver's HDOP (0: not reported). Starts the filter at the first fix that has a course.
  /// True when its position was taken (not rejected).
  bool AddFix(GpsTime t, const Eigen::Vector3d& p_antenna_N_m, const Eigen::Vector3d& pos_std_m,
              bool has_velocity, const Eigen::Vector3d& v_antenna_N_mps,
              const Eigen::Vector3d& vel_std_mps, double hdop);

  bool ready() const { return ready_; }
  GpsTime time() const { return t_; }
  const Vector& state() const { return x_; }
  const Matrix& covariance() const { return P_; }
  double height_m() const { return height_m_; }
  double height_std_m() const { return height_std_m_; }
  std::uint64_t rejected() const { return rejected_; }
  std::uint64_t restarts() const { return restarts_; }

  /// The body point's state carried to t by the model (no measurement), with its covariance.
  void PredictTo(GpsTime t, Vector& x, Matrix& P) const;

 private:
  void Start(GpsTime t, const Eigen::Vector3d& p_antenna_N_m, const Eigen::Vector3d& pos_std_m,
             const Eigen::Vector3d& v_antenna_N_mps, const Eigen::Vector3d& vel_std_mps,
             double hdop);
  /// One step of the model over dt (x and P in place).
  void Step(double dt_s, Vector& x, Matrix& P) const;
  template <int M>
  bool Update(const Eigen::Matrix<double, M, 1>& nu, const Eigen::Matrix<double, M, 7>& H,
              const Eigen::Matrix<double, M, M>& R, bool gated);
  double GnssErrorStd(double hdop) const;

  VehicleModelParams p_;
  bool ready_ = false;
  GpsTime t_{};
  Vector x_ = Vector::Zero();
  Matrix P_ = Matrix::Identity();
  double height_m_ = 0, height_std_m_ = 0;
  double gnss_error_std_m_ = 0;  // the correlated error's σ at the last fix's HDOP
  int consecutive_rejected_ = 0;
  std::uint64_t rejected_ = 0, restarts_ = 0;
};

}  // namespace hil::estimator

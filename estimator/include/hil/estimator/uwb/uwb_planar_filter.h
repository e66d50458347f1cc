#pragma once
/// @file
/// navd's UWB mode filter (paper 003): a small planar EKF fusing the corrected UWB position with
/// the WT901C's yaw rate and heading. State x = [p_E, p_N, ψ, v, b] in the planar frame W (the
/// ENU plane): position (m), yaw ψ (rad, counter-clockwise from east), forward speed v (m/s) and
/// the yaw-rate bias b (rad/s). Prediction with the measured yaw rate ω over dt:
///   ψ ← ψ + (ω − b)·dt,  p ← p + v·dt·(cos ψ, sin ψ),  v and b random walks;
/// updates: position (σ per axis, gated by its Mahalanobis distance: NLOS outliers are rejected)
/// and the sensor's yaw (σ, innovation wrapped). Fixed-size Eigen, no allocation.

#include <cstdint>

#include <Eigen/Core>

namespace hil::estimator::uwb {

struct UwbPlanarFilterParams {
  double position_std_m = 0.06;     ///< UWB position 1σ per axis after correction
  double yaw_std_rad = 0.02;        ///< WT901C yaw 1σ (its fusion's heading)
  double rate_noise_radps = 0.005;  ///< yaw-rate white noise (1σ per sample)
  double speed_rw_mps2 = 0.05;  ///< forward-speed random walk, m/s/√s (a platform at a set speed)
  double bias_rw_radps2 = 1e-4;     ///< yaw-rate bias random walk
  double gate_chi2 = 16.0;          ///< position innovation gate (2 dof)
  int reset_after_rejections = 10;  ///< consecutive gated fixes before a restart
  double init_speed_std_mps = 0.5;
  double init_bias_std_radps = 0.01;
};

struct UwbPlanarFilterStats {
  std::uint64_t predictions = 0, position_updates = 0, yaw_updates = 0, position_rejected = 0,
                resets = 0;
};

class UwbPlanarFilter {
 public:
  using Vector5d = Eigen::Matrix<double, 5, 1>;
  using Matrix5d = Eigen::Matrix<double, 5, 5>;
  explicit UwbPlanarFilter(const UwbPlanarFilterParams& p = {}) : params_(p) {}

  void Initialize(const Eigen::Vector2d& p_W_m, double yaw_rad);
  bool initialized() const { return initialized_; }
  /// Propagates by dt with the measured yaw rate (rad/s).
  void Predict(double yaw_rate_radps, double dt_s);
  /// A UWB position; false when the gate rejects it (after `reset_after_rejections` in a row the
  /// filter restarts at the fix, keeping its yaw).
  bool UpdatePosition(const Eigen::Vector2d& p_W_m);
  void UpdateYaw(double yaw_rad);

  Eigen::Vector2d position() const { return x_.head<2>(); }
  double yaw_rad() const { return x_[2]; }
  double speed_mps() const { return x_[3]; }
  double rate_bias_radps() const { return x_[4]; }
  Eigen::Vector2d position_std_m() const;
  const UwbPlanarFilterStats& stats() const { return stats_; }

 private:
  void Update1(const Eigen::Matrix<double, 1, 5>& h, double innovation, double variance);
  UwbPlanarFilterParams params_;
  Vector5d x_ = Vector5d::Zero();
  Matrix5d p_ = Matrix5d::Identity();
  bool initialized_ = false;
  int rejected_in_row_ = 0;
  UwbPlanarFilterStats stats_;
};

}  // namespace hil::estimator::uwb

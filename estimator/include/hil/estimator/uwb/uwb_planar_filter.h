#pragma once
/// @file
/// navd's UWB mode filter (paper 003): a small planar EKF fusing the corrected UWB position with
/// the WT901C's yaw rate and heading. State x = [p_E, p_N, ψ, v, b, r_E, r_N, c, ċ] in the planar
/// frame W (the ENU plane): position (m), yaw ψ (rad, counter-clockwise from east), forward speed
/// v (m/s), the yaw-rate bias b (rad/s), the UWB fix's residual error r (m) that the correction
/// leaves (paper 003's Table 2: decimetres before, centimetres after, and not white: the same
/// where the tag stands), and the sensor yaw's offset c (rad) with its drift ċ (rad/s): the
/// WT901C's heading comes from its own fusion, whose yaw drifts. Prediction over dt with the
/// measured yaw rate ω:
///   ψ ← ψ + (ω − b)·dt,  p ← p + v·dt·(cos ψ, sin ψ),  v and b random walks,
///   r ← φ·r with φ = exp(−d / residual_distance_m) and variance σ_r²(1 − φ²) added: a
///   Gauss–Markov process in the distance d travelled (it holds while the tag stands still),
///   c ← c + ċ·dt (c a slow random walk, ċ a random constant);
/// updates: position z = p + r + white (σ per axis, gated by its Mahalanobis distance: NLOS
/// outliers are rejected) and the sensor's yaw z = ψ + c + white (innovation wrapped). Without r
/// a tag standing still averaged its fixes down to millimetres of σ around a centimetres-wrong
/// position (mean horizontal NEES 41 over seed003_static_uwb); without c the sensor's drifted yaw
/// (3° after 13 min there) held the heading and the track ran 0.36 m off the fixes on a 6.5 m
/// leg. Fixed-size Eigen, no allocation.

#include <cstdint>

#include <Eigen/Core>

namespace hil::estimator::uwb {

struct UwbPlanarFilterParams {
  double position_std_m = 0.06;  ///< UWB position's white 1σ per axis after correction
  /// 1σ per axis of the residual error the correction leaves (0: not modelled). Ours: paper 003's
  /// Table 2 gives the mean |error| of 100-sample averages after correction, 0.028 m (X) and
  /// 0.055 m (Y); a Gaussian's mean |e| is 0.8 σ, so 0.035 / 0.069 m: one σ of 0.05 for both axes.
  double residual_std_m = 0.05;
  /// distance over which the residual decorrelates (m). Ours (the paper gives none): a ranging
  /// residual is set by the geometry to the anchors and their reflectors, which changes over
  /// metres; 2 m.
  double residual_distance_m = 2.0;
  /// prior 1σ of the sensor yaw's offset (rad). Ours: 1°, ten times paper 003's quoted 0.1°
  /// accuracy of the WT901C (a bench figure; on a vehicle its magnetometer-aided fusion meets iron
  /// and motors). 5° let the UWB track's noise into the heading: line-following RMSE +30 %.
  double yaw_offset_std_rad = 1.0 * 0.017453292519943295;
  /// prior 1σ of its drift (rad/s; ours: 0.01°/s, a consumer MEMS gyro's residual bias after the
  /// sensor's own calibration); the offset also walks by this × 1 √s per √s
  double yaw_drift_std_radps = 0.01 * 0.017453292519943295;
  double yaw_std_rad = 0.02;        ///< WT901C yaw's white 1σ (its fusion's heading)
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
  static constexpr int kStates = 9;
  static constexpr int kResidual = 5;   ///< r_E, r_N
  static constexpr int kYawOffset = 7;  ///< c, then ċ
  using Vector9d = Eigen::Matrix<double, kStates, 1>;
  using Matrix9d = Eigen::Matrix<double, kStates, kStates>;
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
  Eigen::Vector2d residual_m() const { return x_.segment<2>(kResidual); }
  double yaw_offset_rad() const { return x_[kYawOffset]; }
  const UwbPlanarFilterStats& stats() const { return stats_; }

 private:
  void Update1(const Eigen::Matrix<double, 1, kStates>& h, double innovation, double variance);
  void PredictResidual(double distance_m);
  UwbPlanarFilterParams params_;
  Vector9d x_ = Vector9d::Zero();
  Matrix9d p_ = Matrix9d::Identity();
  bool initialized_ = false;
  int rejected_in_row_ = 0;
  UwbPlanarFilterStats stats_;
};

}  // namespace hil::estimator::uwb

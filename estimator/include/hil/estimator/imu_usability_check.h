#pragma once
/// @file
/// Is the IMU usable? The accelerometer against the GNSS, independent of the filter's state
/// (estimator.md, "An IMU that cannot be used").
///
/// Over a window between two GNSS velocity fixes (about `window_s`), the mean specific force the
/// IMU measured, integrated in the body frame of the window's start with the gyro increments, is
/// compared in magnitude with the specific force the GNSS velocities imply,
///   m = |Σ C_B0_B Δv_B / T| − |(v_b − v_a)/T − g_N|.
/// A magnitude needs no attitude, so the broken IMU's attitude does not enter. For a usable IMU m
/// is its bias and scale error along gravity, constant but for the bias random walk the filter is
/// configured with; an IMU whose apparent bias wanders (an engine order aliased near DC by a
/// point-sampled read-out: field_realism/two_stroke_robot) makes m wander by far more.
/// Test: the last `windows` values of m (K; from `min_windows` on while fewer have been seen)
/// against a common mean, Λ = Σ (m_i − m̄)² / σ_i² with the weighted mean m̄, which is χ²(K − 1) for
/// K independent windows of equal mean (the χ² test of homogeneity of means; Cochran, "The
/// combination of estimates from different experiments", Biometrics 10, 1954). σ_i² is the IMU
/// mean's variance by batch means (1 s blocks, the block means' scatter over their number:
/// correlated vibration is in it; Schmeiser, "Batch size effects in the analysis of simulation
/// experiments", Operations Research 30(3), 1982), not below the configured white noise's, plus the
/// GNSS acceleration's from the two velocities' σ, plus the configured bias random walk over the
/// test's span (q²·K·T/6: the scatter of a random walk's samples about their mean, approximately).
/// The IMU is unusable once Λ exceeds the χ²(K − 1) quantile of `enter_z` (Wilson–Hilferty;
/// z 4.753: 1e-6 false alarms per test of a consistent IMU, one in 58 days of 5 s tests; WH
/// gives 49.9 for K = 12 where the exact quantile is 48.9), usable again once Λ has stayed below
/// the quantile of `leave_z` (1.645: 95 %) for `leave_tests` tests in a row (hysteresis: K more
/// windows, so the test's span is wholly new). Window 5 s, K 12, blocks 1 s: ours (a 1 Hz
/// receiver's velocity difference resolves 3 cm/s² over 5 s; the first test after 15 s, a span of
/// a minute; 10 s windows, K 6, decided 15 s later on two_stroke_robot, whose INS was metres off
/// by then). No allocation.

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "hil/estimator/time_types.h"

namespace hil::estimator {

struct ImuUsabilityParams {
  bool enabled = true;
  double window_s = 5.0;       ///< one window between GNSS velocity fixes (ours)
  double block_s = 1.0;        ///< batch-means block (ours)
  int windows = 12;            ///< K windows in a test (ours) …
  int min_windows = 3;         ///< … fewer (not below this) until that many have been seen
  double enter_z = 4.753;      ///< unusable above χ²(K−1) at this normal quantile (1e-6)
  double leave_z = 1.645;      ///< usable again below this one (95 %) …
  int leave_tests = 12;        ///< … for this many tests in a row
  double max_fix_gap_s = 2.5;  ///< GNSS velocities further apart end the window unused
};

class ImuUsabilityCheck {
 public:
  ImuUsabilityCheck() = default;
  /// `accel_noise_mps2_rthz` and `accel_bias_rw_mps3_rthz`: the filter's configured model.
  ImuUsabilityCheck(const ImuUsabilityParams& p, double accel_noise_mps2_rthz,
                    double accel_bias_rw_mps3_rthz)
      : p_(p),
        accel_noise_(accel_noise_mps2_rthz),
        bias_rw_(accel_bias_rw_mps3_rthz),
        dof_(p.windows - 1) {}

  /// One IMU interval: gyro increment (bias removed as far as known) and raw velocity increment.
  void AddImu(const Eigen::Vector3d& delta_angle_B_rad, const Eigen::Vector3d& delta_velocity_B_mps,
              double dt_s);
  /// A GNSS velocity (antenna, N) with its σ, and gravity in N; closes a window when one is due.
  /// True when a test ran (its statistic is statistic()).
  bool AddGnssVelocity(GpsTime t, const Eigen::Vector3d& v_N_mps, const Eigen::Vector3d& std_mps,
                       const Eigen::Vector3d& g_N_mps2);

  bool unusable() const { return unusable_; }
  /// Λ of the last test, its degrees of freedom (windows in it − 1; K − 1 before the first
  /// test), and the thresholds for those.
  double statistic() const { return statistic_; }
  int dof() const { return dof_; }
  double enter_threshold() const;
  double leave_threshold() const;
  std::uint64_t tests() const { return tests_; }
  std::uint64_t unusable_periods() const { return periods_; }
  /// The last window's m and its σ (for tests and reports).
  double last_mismatch_mps2() const { return last_m_; }
  double last_mismatch_std_mps2() const { return last_std_; }

 private:
  void StartWindow(GpsTime t, const Eigen::Vector3d& v_N_mps, const Eigen::Vector3d& std_mps);
  /// Closes the window at a fix: its mismatch and variance into the ring, then the test.
  void CloseWindow(double span_s, const Eigen::Vector3d& v_N_mps, const Eigen::Vector3d& std_mps,
                   const Eigen::Vector3d& g_N_mps2);
  void Test();

  static constexpr int kMaxBlocks = 64;
  static constexpr int kMaxWindows = 16;
  ImuUsabilityParams p_;
  double accel_noise_ = 0, bias_rw_ = 0;
  // the open window
  std::optional<GpsTime> start_t_, last_fix_t_;
  Eigen::Vector3d v_start_ = Eigen::Vector3d::Zero(), std_start_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_B0_B_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d dv_B0_ = Eigen::Vector3d::Zero(), block_dv_ = Eigen::Vector3d::Zero();
  double T_ = 0, block_T_ = 0;
  std::array<Eigen::Vector3d, kMaxBlocks> blocks_{};
  int n_blocks_ = 0;
  // closed windows: mismatch and its variance
  std::array<double, kMaxWindows> m_{}, var_{};
  int next_ = 0, count_ = 0;
  double statistic_ = 0, last_m_ = 0, last_std_ = 0;
  int dof_ = 0;
  bool unusable_ = false;
  int passes_ = 0;
  std::uint64_t tests_ = 0, periods_ = 0;
};

}  // namespace hil::estimator

#pragma once
/// @file
/// @system
/// name: GnssStepCheck (consistency of consecutive GNSS fixes with the INS displacement)
/// input: each fix's antenna position and σ (N, m), the INS-predicted antenna position before the
///        update and its velocity variance; the filter's antenna position after the fix
/// output: whether the fixes stepped where the INS did not (a receiver jump)
/// @endsystem
///
/// Tells a receiver that jumps (a glitch, multipath, a wrong fix) from a filter whose model is
/// wrong. Between two fixes a short interval apart the INS displacement is good even when the IMU
/// noise model is far off (its error grows with the interval squared), so the difference
///   d = (p_k − p_{k−1}) − (p̂_k⁻ − p̂_{k−1}⁺)
/// of the fixes' increment and the INS-propagated displacement is the receiver's own step. A wrong
/// model makes the innovations large and the increments consistent; a jump makes one increment
/// large (at its start and at its end) and the innovations in between large. No allocation.
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/time_types.h"

namespace hil::estimator {

/// Parameters of the step test (chosen here; no source gives them).
struct GnssStepParams {
  /// |d| above this many σ of d (the two fixes' σ and the INS displacement's, largest axis) is a
  /// step: the navigator's update gate
  double gate_sigma = 5.0;
  /// and above this floor: an RTK receiver's σ of a centimetre would otherwise make a wrong
  /// IMU model's displacement error over one fix interval (a few centimetres) look like a step.
  /// 1 m: a ground vehicle's INS does not mis-predict its displacement by a metre within
  /// max_interval while fixes keep coming, a glitch of interest (multipath, a wrong fix) is metres.
  double min_step_m = 1.0;
  /// fixes further apart are not compared (the INS displacement over a gap is not good enough)
  Nanoseconds max_interval{1'500'000'000};
};

class GnssStepCheck {
 public:
  GnssStepCheck() = default;
  explicit GnssStepCheck(const GnssStepParams& params) : params_(params) {}

  /// The fix at t (antenna position p_fix_N_m with per-axis σ) against the previous one, with the
  /// INS-predicted antenna position p_ins_N_m before this fix's update and the variance per axis
  /// of the filter's velocity. True when the fixes stepped where the INS did not.
  bool IsStep(GpsTime t, const Eigen::Vector3d& p_fix_N_m, const Eigen::Vector3d& fix_std_m,
              const Eigen::Vector3d& p_ins_N_m, const Eigen::Vector3d& vel_var_N_m2ps2);
  /// Remembers the fix and the filter's antenna position after it (update or reset applied).
  void Remember(GpsTime t, const Eigen::Vector3d& p_fix_N_m, const Eigen::Vector3d& fix_std_m,
                const Eigen::Vector3d& p_ins_after_N_m);
  /// The last step's size |d| (m), for the health output.
  double last_step_m() const { return last_step_m_; }

 private:
  GnssStepParams params_;
  std::optional<GpsTime> prev_t_;
  Eigen::Vector3d prev_fix_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d prev_std_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d prev_ins_ = Eigen::Vector3d::Zero();
  double last_step_m_ = 0;
};

}  // namespace hil::estimator

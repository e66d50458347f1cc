#pragma once
/// @file
/// Paper 001's guidance as a whole (seeds_001_003.md A.8–A.12): a base row-following navigation
/// that steers from the estimate (pure pursuit along the planned aisle centre lines, as move_base
/// would from the EKF's pose) with the paper's deviation corrector layered over it
/// (deviation_corrector.h) for a differential-drive base.
///
/// - The corrector sees the four ranges and the estimate's heading (navd's gyro + odometry
///   filter: the gyro's integrated heading with its bias fed back) and yaw rate; while it corrects,
///   its command replaces the base navigation's.
/// - **Re-anchoring (this project's, not the paper's):** the base navigation steers to where the
///   estimate says the line is, so it would undo a correction at once. When a correction ends
///   (the corrector returns to following), the ranges say where the vehicle is: DP left of the set
///   line (perpendicular to the rows) and AP from the rows' direction. The navigation's pose is
///   re-anchored there by a rigid 2-D transform (rotation about the vehicle by δψ, then a shift
///   perpendicular to the path) applied to every later estimate, so that the base navigation
///   carries the correction on instead of fighting it. Only on a straight segment of the path;
///   DP and AP are the means of the last `anchor_samples` range sets.
/// - Without the correction (`correction = false`) the command is the base navigation's alone.
/// Wheel speeds from (v, ω): v_R,L = v ± ω·track/2, both scaled down together at the limit.
/// Fixed-size state, no allocation.

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "hil/estimator/guidance/deviation_corrector.h"
#include "hil/estimator/guidance/path_tracker.h"
#include "hil/estimator/guidance/planned_path.h"
#include "hil/estimator/guidance/vehicle.h"

namespace hil::estimator::guidance {

struct RowFollowerConfig {
  double speed_mps = 0.4;
  PurePursuitConfig pursuit;
  bool correction = true;
  /// A range beyond this sees no ridge beside the vehicle (the headland, a far wall): the set is
  /// not used, and a correction under way is abandoned (ours: 3 × D_set).
  double max_ridge_range_m = 1.5;
  /// The re-anchoring takes DP and AP as the mean of this many last range sets (ours: one range's
  /// noise, ~5 mm, over p_dist = 0.4 m is ~1° of AP; 20 sets at 100 Hz bring it to ~0.2°).
  int anchor_samples = 20;
  DeviationCorrectorConfig corrector;
};

struct RowFollowerState {
  std::uint64_t anchors = 0;
  double anchor_yaw_rad = 0;  ///< the re-anchoring transform's rotation
  Eigen::Vector2d anchor_shift_m{0, 0};
  bool end_of_path = false;
};

class RowFollower {
 public:
  RowFollower(const RowFollowerConfig& c, const PlannedPath& path);
  /// The estimate at time t (its yaw unwrapped inside); feeds the corrector's gyro heading.
  void OnEstimate(GpsTime t, const VehiclePose2d& estimate);
  void OnRanges(const RangeSet& r);
  /// The command at the last estimate.
  VelocityCommand Command();
  const DeviationCorrector& corrector() const { return corrector_; }
  const RowFollowerState& state() const { return state_; }
  /// The estimate through the re-anchoring transform.
  VehiclePose2d Anchored(const VehiclePose2d& estimate) const;

 private:
  void ReAnchor();
  RowFollowerConfig config_;
  const PlannedPath& path_;
  PurePursuit pursuit_;
  DeviationCorrector corrector_;
  VehiclePose2d estimate_;
  GpsTime last_t_{};
  double yaw_unwrapped_rad_ = 0, last_yaw_rad_ = 0;
  bool have_estimate_ = false, was_correcting_ = false;
  RowFollowerState state_;
  static constexpr int kMaxAnchorSamples = 128;
  std::array<double, kMaxAnchorSamples> dp_ring_{}, ap_ring_{};
  int anchor_pos_ = 0, anchor_fill_ = 0;
};

/// v_R,L = v ± ω·track/2 over the wheel radius, both scaled down together at the wheel limit.
WheelSpeeds WheelSpeedsFromSpeedAndYawRate(const DiffDrivePlatform& p, double v_mps,
                                           double w_radps);

}  // namespace hil::estimator::guidance

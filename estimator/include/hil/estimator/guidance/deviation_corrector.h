#pragma once
/// @file
/// Paper 001's deviation corrector (seeds_001_003.md A.8–A.12): four laser rangefinders (right
/// and left, front and rear) and the gyro hold a differential-drive vehicle on an inter-ridge
/// aisle, layered over the base navigation's velocity command (V_d, ω_d).
///
/// - Lateral offset DP = (C1 + C2)/2 − D_set from the two right-side ranges (C1 front, C2 rear;
///   the mean is the digest's reading of the lost equation), heading offset
///   AP = atan((C1 − C2)/p_dist) (> 0: the vehicle points left of the rows). D_set = 0.5 m,
///   D_m = 30 mm, A_m = 5° (the paper's).
/// - Heading correction (|AP| > A_m, first): the vehicle stops and turns in place (V = 0) until
///   the gyro heading reaches the heading at the trigger minus AP ("until the gyro's heading
///   offset returns to zero"); ω = clamp(k_ψ·e, ±ω_max).
/// - Lateral correction (|DP| > D_m): the vehicle keeps V_d and steers along a 45° oblique towards
///   the set distance, tapering to the rows' direction within `taper_offset_m` of it; DP is taken
///   perpendicular to the rows (ranges × cos of the heading relative to the rows, the row
///   direction from the gyro and AP at the trigger). It ends when at least 50 of the last 100
///   range samples have |DP| ≤ D_m, then the heading returns to the rows' direction.
/// - Only on straight segments: a turn is recognised when the gyro's yaw rate exceeds
///   `turn_rate_radps` while the left and right mean ranges change in opposite directions
///   (left falling and right rising: a left turn), and is held `turn_hold` after; corrections
///   neither start nor run during one. The corrector's own motions (its turns in place and its
///   oblique swerves, which show the same signs) are not recognised as turns. No correction
///   starts without four valid ranges.
/// The paper's missing laws (ω_t, V_t, ω_t′ and their combination with V_d, ω_d) are this
/// project's: the gains below are scenario parameters. Fixed-size state, no allocation.

#include <array>
#include <cstdint>

#include "hil/estimator/time_types.h"

namespace hil::estimator::guidance {

struct DeviationCorrectorConfig {
  double d_set_m = 0.5;                         ///< paper
  double d_m_m = 0.030;                         ///< paper
  double a_m_rad = 5.0 * 0.017453292519943295;  ///< paper (5°)
  double p_dist_m = 0.4;                        ///< spacing of the two same-side units (scenario)
  int window = 100, within_needed = 50;         ///< paper: ≥ 50 of 100 samples within D_m
  double approach_rad = 45.0 * 0.017453292519943295;  ///< paper's 45° oblique
  double taper_offset_m = 0.10;      ///< below this |DP| the oblique angle shrinks linearly
  double heading_gain_per_s = 2.0;   ///< k_ψ
  double max_turn_rate_radps = 0.6;  ///< ω_max of every correction
  double heading_tolerance_rad = 0.5 * 0.017453292519943295;  ///< "returns to zero"
  double turn_rate_radps = 15.0 * 0.017453292519943295;       ///< turn recognition
  double range_rate_mps = 0.15;          ///< |d range/dt| of each side for a turn
  int range_rate_samples = 10;           ///< the range-rate baseline (samples)
  Nanoseconds turn_hold{1'000'000'000};  ///< a turn lasts this long after its signs end
};

/// One rangefinder cycle (metres; a range counts only when its flag is set).
struct RangeSet {
  GpsTime t{};
  double right_front_m = 0, right_rear_m = 0, left_front_m = 0, left_rear_m = 0;
  bool right_front_ok = false, right_rear_ok = false, left_front_ok = false, left_rear_ok = false;
};

/// The gyro's integrated heading (counter-clockwise, unwrapped) and its yaw rate.
struct GyroHeading {
  GpsTime t{};
  double yaw_rad = 0, yaw_rate_radps = 0;
};

struct VelocityCommand {
  double v_mps = 0, w_radps = 0;  ///< forward speed, yaw rate (counter-clockwise)
};

enum class CorrectionMode { kFollow, kTurn, kHeading, kLateral, kRealign };

struct DeviationState {
  CorrectionMode mode = CorrectionMode::kFollow;
  double dp_m = 0, ap_rad = 0;  ///< the last DP (perpendicular to the rows) and AP
  int within = 0;               ///< samples of the window within D_m
  std::uint64_t lateral_corrections = 0, heading_corrections = 0, turns = 0;
};

class DeviationCorrector {
 public:
  explicit DeviationCorrector(const DeviationCorrectorConfig& config);
  void OnGyro(const GyroHeading& g);
  void OnRanges(const RangeSet& r);
  /// The command to send: the base navigation's, or the correction's in its place.
  VelocityCommand Command(const VelocityCommand& base) const;
  /// Ends a correction under way without finishing it (the vehicle left the rows): follow.
  void Abandon();
  const DeviationState& state() const { return state_; }

 private:
  static constexpr int kMaxWindow = 256, kMaxRateSamples = 64;
  bool RecogniseTurn(const RangeSet& r);
  void Decide(const RangeSet& r, double ap_rad, double dp_m);
  void PushWithin(bool within);
  double RelativeHeading() const { return gyro_.yaw_rad - row_yaw_rad_; }

  DeviationCorrectorConfig config_;
  DeviationState state_;
  GyroHeading gyro_;
  double row_yaw_rad_ = 0, target_yaw_rad_ = 0;
  GpsTime turn_until_{};
  std::array<bool, kMaxWindow> within_ring_{};
  int ring_pos_ = 0, ring_fill_ = 0;
  std::array<double, kMaxRateSamples> left_ring_{}, right_ring_{};
  std::array<GpsTime, kMaxRateSamples> time_ring_{};
  int rate_pos_ = 0, rate_fill_ = 0;
};

}  // namespace hil::estimator::guidance

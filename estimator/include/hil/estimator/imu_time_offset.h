#pragma once
/// @file
/// @system
/// name: ImuTimeOffset (online estimate of the lag of the IMU's time tags behind GNSS time)
/// input: IMU samples as tagged (their heading increment about the local vertical, bias removed);
///        GNSS fixes with a velocity (their course over ground and its σ)
/// output: the IMU tag lag L (s; the sample tagged t was sensed at t − L) once the evidence for
///         it is conclusive, with its σ and the evidence
/// @endsystem
///
/// A lagging IMU makes the filter predict where the vehicle was L ago: in a turn every prediction
/// misses by the distance the lag's heading change moves it, fixes are rejected and the filter
/// resets (the car drive of issue 39: a consumer MEMS tagged 0.1 s late against 10 Hz RTK).
/// The lag is found as a time-delay estimate (Knapp and Carter, "The generalized correlation
/// method for estimation of time delay", IEEE Trans. ASSP 24(4), 1976: the delay that best aligns
/// two records of one signal) between the GNSS course increments and the gyro's heading
/// increments over the same intervals. For every candidate lag L_j on a grid, each pair of fixes
/// about `pair_interval_s` apart (k−1, k; pairs do not overlap, so their residuals are
/// independent) adds the weighted squared residual
///   r² / σ² with r = wrap(χ_k − χ_{k−1}) − (χ̂_j(t_k) − χ̂_j(t_{k−1})),
/// χ the GNSS course of the antenna, χ̂_j(t) = ψ(t + L_j) + asin(ω l_x / s) the antenna's
/// course the IMU predicts for that lag (ψ its integrated heading on its own tags, ω its heading
/// rate over ±`rate_half_window_s`, l the antenna's lever arm, s the fix's speed: the antenna's
/// velocity in the body is (v − ω l_y, ω l_x), so an antenna ahead of the body turns its course
/// ahead of the heading, which would otherwise read as a lead of l_x / v), both courses averaged
/// alike over the fixes within `course_window_s` (the ride's shaking of the IMU's heading),
/// σ² the two courses' variances (σ_v / speed each) plus a floor for what the course does not
/// share with the heading (side slip). The sums forget with a time constant; their minimum over
/// the grid (refined by a parabola through its neighbours) is the lag, its curvature gives the σ
/// (the sums are −2 log-likelihoods, scaled by their own residual variance per pair: the
/// a-posteriori variance factor of least squares, as the receiver's quoted velocity σ is seldom
/// its real one), and the lag is reported only when zero lag is worse by a χ² evidence margin and
/// the σ is small: straight driving gives no evidence, a lag-free IMU none against zero.
/// A time-offset state in the EKF (Skog and Händel, "Time synchronization errors in loosely
/// coupled GPS-aided inertial navigation systems", IEEE Trans. ITS 12(4), 2011) was weighed: it
/// adds a state to every prediction, and at a 0.1 s lag the linearisation p + v·δt misses by
/// ½ a δt² (1.5 cm at 3 m/s²) in the turns that make the offset observable.
/// Fixed-size buffers, no allocation.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "hil/estimator/ring_buffer.h"
#include "hil/estimator/time_types.h"

namespace hil::estimator {

/// Parameters (chosen here; no source gives them).
struct ImuTimeOffsetParams {
  bool enabled = true;
  double min_lag_s = -0.1;     ///< the candidate grid: IMU tags up to 0.1 s early …
  double max_lag_s = 0.3;      ///< … to 0.3 s late (above the 0.1 s of issue 39's car)
  double step_s = 0.005;       ///< grid step (half a sample at 100 Hz; refined by a parabola)
  double min_speed_mps = 0.5;  ///< a course below this speed is not used
  /// fixes further apart are not paired (at 1 Hz the increments still hold a turn's heading change)
  Nanoseconds max_fix_interval{1'500'000'000};
  /// course-increment σ floor (rad): side slip
  double course_floor_rad = 0.003;
  /// fixes are paired this far apart at least (a turn's entry is a second or two: the course noise
  /// is white per fix, the lag's signal grows with the interval)
  double pair_interval_s = 1.0;
  double rate_half_window_s = 0.05;  ///< the heading rate for the lever arm's course
  /// Both records are prefiltered alike (the "generalized" of Knapp and Carter's correlation): a
  /// fix's course and the course the IMU predicts are each averaged over the fixes within this
  /// window centred on it (s; 0: the fix alone). A vehicle's ride shakes the IMU about its heading
  /// (a tractor: 0.3 °/s r.m.s. in 1-15 Hz and its 1.5-1.9 Hz roll mode, imu_error_model.md) and
  /// the lever arm's ω l_x / v amplifies that by 2π f l_x / v (13 at 1.8 Hz for 1.2 m at 1 m/s):
  /// milliradians per fix that each candidate lag samples anew, so that the costs' differences
  /// grew with the pairs and a lag-free IMU read as 0.21-0.29 s late
  /// (field_realism/tractor_engine_vibration). A mean over 1 s passes at most 1/(π f · 1 s) of a
  /// ride above 1 Hz (≤ 0.16 in 1.2-2.5 Hz); applied to both records it delays neither, where the
  /// IMU's heading alone smoothed biased the lag at a turn's corners (chosen here).
  double course_window_s = 1.0;
  double memory_s = 600.0;  ///< forgetting time constant of the sums
  /// zero lag must be worse than the best by this much (χ²: 5 σ) …
  double evidence = 25.0;
  double max_std_s = 0.01;  ///< … and the lag's σ below this, before the lag is reported
  /// The navigator takes a found lag off the IMU tags gradually: slewing the time base at a rate s
  /// (per second) makes the filter's INS run v·s ahead of (or behind) the fixes it has been
  /// following, which its position must absorb between fixes; s = this / speed, at most 0.1.
  /// 0.05 m/s: a few millimetres per fix at 10 Hz, inside an RTK fix's σ (chosen here).
  double slew_speed_mps = 0.05;
  /// Once the tags have moved by this much since the gyro triad's states (the z scale, the x and
  /// y couplings to the z rate) started, and the slew has reached the lag, those states restart
  /// at their prior: in the turns before, the lag's heading and tilt errors taught them (0.1 s on
  /// the car: a 2.8° x coupling in the first turn, against 0.1° with the tags on time). 10 ms,
  /// max_std_s: a change within the lag's own σ bound is not a new time base (chosen here).
  double gyro_states_restart_s = 0.01;
};

class ImuTimeOffset {
 public:
  /// Candidates at most (the grid's points beyond it are dropped).
  static constexpr int kMaxCandidates = 96;

  ImuTimeOffset() : ImuTimeOffset(ImuTimeOffsetParams{}) {}
  explicit ImuTimeOffset(const ImuTimeOffsetParams& params);

  /// The GNSS antenna's lever arm in the body frame (forward x, left y; m).
  void SetLeverArm(double x_m, double y_m) {
    lever_x_m_ = x_m;
    lever_y_m_ = y_m;
  }
  /// One IMU sample as tagged (its interval ends at t): its heading increment about the local
  /// vertical (rad, counter-clockwise, gyro bias removed).
  void AddImu(GpsTime t, double heading_increment_rad);
  /// One GNSS fix's velocity (ENU, m/s) and the σ of one horizontal component. Fixes must come in
  /// time order (others are ignored); each is used once the IMU history covers it.
  void AddVelocity(GpsTime t, double v_east_mps, double v_north_mps, double std_mps);

  /// The lag once conclusive (s; the sample tagged t was sensed at t − lag).
  std::optional<double> lag_s() const {
    return conclusive_ ? std::optional<double>(lag_s_) : std::nullopt;
  }
  /// The best lag on the evidence so far, its σ and the evidence against zero lag (J(0) − J_min).
  double best_lag_s() const { return lag_s_; }
  double lag_std_s() const { return lag_std_s_; }
  double evidence() const { return evidence_; }
  int increments() const { return increments_; }  ///< course increments used

 private:
  struct Heading {
    std::int64_t t_ns = 0;
    double psi_rad = 0;  ///< integrated heading at the end of the sample
  };
  struct Course {
    std::int64_t t_ns = 0;
    double chi_rad = 0, var_rad2 = 0, speed_mps = 0;
  };
  static constexpr std::size_t kMaxWindowFixes = 64;
  /// A fix's course averaged over course_window_s: the mean course, its variance, the fixes' times
  /// and speeds (the IMU's prediction is averaged over the same).
  struct WindowedCourse {
    std::int64_t t_ns = 0;
    double chi_rad = 0, var_rad2 = 0;
    std::size_t n = 0;
    std::array<std::int64_t, kMaxWindowFixes> t_fix_ns{};
    std::array<double, kMaxWindowFixes> speed_mps{};
  };
  /// The IMU's predicted course for every candidate lag (j < n_), a windowed course's mean.
  using Courses = std::array<double, kMaxCandidates>;
  /// ψ at t by linear interpolation; nullopt outside the history. `from`: an index of history_
  /// at or before the first entry at or after t (a later t's search starts there: the candidates'
  /// times ascend), or SIZE_MAX for a binary search; it is moved to that entry.
  std::optional<double> HeadingAt(std::int64_t t_ns, std::size_t& from) const;
  /// The antenna course the IMU predicts at t for a lag (nullopt outside the history), the
  /// heading rate over ± h (rate_half_window_s); `from`: a search start per time read (ψ at t − h,
  /// t, t + h), as in HeadingAt.
  std::optional<double> PredictedCourse(std::int64_t t_ns, std::int64_t lag_ns, std::int64_t h_ns,
                                        double speed_mps, std::array<std::size_t, 3>& from) const;
  /// The IMU's predicted course averaged over a windowed course's fixes, for every candidate lag
  /// (`out`); false when the history does not cover them all.
  bool PredictedMeanCourses(const WindowedCourse& w, Courses& out) const;
  /// The same, taken from the last pair's second course when `w` is it and the history still holds
  /// every IMU sample it read (the same values: the history's entries do not change).
  bool PredictedMeanCoursesOfPrevious(const WindowedCourse& w, Courses& out) const;
  /// A fix the IMU history covers: kept until every window that holds it is complete.
  void Use(const Course& c);
  /// The course window_[i]'s average over its window.
  WindowedCourse WindowAround(std::size_t i) const;
  void UsePair(const WindowedCourse& c);
  void Estimate();

  ImuTimeOffsetParams params_;
  int n_ = 0;  ///< candidates in use
  std::array<double, kMaxCandidates> cost_{};
  RingBuffer<Heading, 1024> history_;  // 10 s at 100 Hz: a fix delayed by the GNSS wait included
  RingBuffer<Course, 64> pending_;
  RingBuffer<Course, kMaxWindowFixes> window_;  // the IMU history covers them
  std::int64_t last_centre_ns_ = INT64_MIN;     // the last fix whose window was used
  std::optional<WindowedCourse> prev_;
  // prev_'s predicted mean courses (PredictedMeanCourses, when it was the pair's second course),
  // the earliest IMU time they read and the lever arm they took; the next pair reuses them
  Courses prev_courses_{};
  std::int64_t prev_courses_t_ns_ = INT64_MIN, prev_courses_earliest_ns_ = INT64_MIN;
  double prev_courses_lever_x_m_ = 0;
  double psi_rad_ = 0;
  double lever_x_m_ = 0, lever_y_m_ = 0;
  double pairs_ = 0;  // pairs in the sums (forgotten as they are)
  double lag_s_ = 0, lag_std_s_ = 0, evidence_ = 0;
  bool conclusive_ = false;
  int increments_ = 0;
};

}  // namespace hil::estimator

#pragma once
/// @file
/// Paper 003's path tracker (seeds_001_003.md §B.6): an analytic fuzzy rule with a self-adjusting
/// weight. The lateral deviation d (m, + = vehicle left of the line) and the heading deviation θ
/// (path direction minus vehicle yaw, + = counter-clockwise) are quantised to the fuzzy domain
/// [−S, S] (S = 6; k_d = S/0.6 m = 10, k_θ = S/60° = 0.1 per degree); the weight n = k·|d/M|^p
/// (eq. 10: M = 0.6 m, p = 0.8, k = 1.1), clamped to [0, 1], mixes them into the fuzzy front-wheel
/// angle A, and α = k_α·A (α > 0 = left), clamped to ±32°. The controller answers with the
/// curvature κ = tan α / L of the front-steered platform (wheelbase L).
///
/// How the paper's three inconsistencies are resolved (estimator/src/guidance/README.md):
///  - eq. 9, A = n(S − |D|) + (1 − n)(S − |Θ|), carries no sign and is largest at zero deviation.
///    Here A = n·(−D) + (1 − n)·Θ: the signed analytic rule whose magnitude, when D and Θ ask
///    for the same turn, is S minus eq. 9's value (S − A₉ = n|D| + (1 − n)|Θ|). The signs follow
///    the paper's conventions: left of the line (d > 0) steers right, a path direction
///    counter-clockwise of the heading (θ > 0) steers left;
///  - k_α = 0.17 maps [−6, 6] onto neither ±32° nor ±0.56 rad: k_α = 32°/6 = 5.33° per level,
///    so the fuzzy domain spans the push rod's range (a parameter);
///  - n > 1 for |d| > 0.533 m with k = 1.1, p = 0.8: n is clamped to [0, 1].
/// Same interface as PurePursuit (path_tracker.h): Update(path, pose) → TrackingCommand, Reset().
/// Allocation-free.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "hil/estimator/guidance/path_tracker.h"

namespace hil::estimator::guidance {

struct FuzzyTrackerConfig {
  double domain_s = 6.0;            ///< S: the fuzzy domain [−S, S]
  double d_range_m = 0.6;           ///< basic domain of d: k_d = S / d_range
  double theta_range_deg = 60.0;    ///< basic domain of θ: k_θ = S / θ_range
  double alpha_max_deg = 32.0;      ///< the push rod's steering range
  double k_alpha_deg = 32.0 / 6.0;  ///< output scale (° per level); the paper prints 0.17
  double weight_k = 1.1, weight_p = 0.8, weight_m_m = 0.6;  ///< eq. 10
  bool quantise_levels = false;  ///< round A to whole fuzzy levels (−6 … 6) before scaling
  double wheelbase_m = 0.84;     ///< paper 003's platform
  double search_window_m = 5.0;  ///< projection search around the previous foot
  /// The "tracking heading" θ is measured against (the paper does not define it): 0, the path's
  /// direction at the foot; > 0, the bearing from the reference point to the path point this far
  /// (arc length) ahead of the foot, which turns before a corner does (paper 003's scenarios: 2 m,
  /// the baseline pure pursuit's look-ahead, estimator/src/guidance/README.md).
  double heading_preview_m = 0.0;
  /// Upper bound of the weight n (the paper: 1). Below 1 the heading term keeps a share
  /// (1 − n_max) of the rule at every lateral deviation: without it the rule is heading-blind
  /// beyond |d| = 0.533 m and has no damping there (a scenario parameter, not the paper's).
  double weight_n_max = 1.0;
  /// Anti-windup at the steering actuator: the commanded α moves at most this fast (°/s, 0 = no
  /// limit), so the command never runs ahead of a rate-limited push rod and the rule sees the
  /// angle the wheels can actually hold (a scenario parameter). The step of one Update is this
  /// rate times the interval between the poses' solution times (VehiclePose2d::t_ns), see
  /// FuzzyUpdateInterval_s.
  double steer_rate_limit_deg_s = 0.0;
  /// The interval assumed when the solution times cannot give one: the first Update after
  /// construction or Reset, a pose without t_ns, or a time that goes backwards (paper 003: 5 Hz).
  double fallback_period_s = 0.2;
};

/// n = k·|d/M|^p clamped to [0, 1] (eq. 10).
double FuzzyWeight(const FuzzyTrackerConfig& c, double d_m);
/// The front-wheel angle α (rad, + = left) for lateral deviation d (m, + = left of the line) and
/// heading deviation θ (rad, path minus vehicle, + = counter-clockwise).
double FuzzySteerAngle_rad(const FuzzyTrackerConfig& c, double d_m, double theta_rad);
/// The interval (s) between two solution times (ns): t_ns − prev_t_ns taken modulo one day, so
/// that a UTC time of day works across midnight; 0 for a repeated time (the rod has had no time
/// to move). c.fallback_period_s when either time is missing or the difference, so wrapped, is
/// 12 h or more (a time that went backwards).
double FuzzyUpdateInterval_s(const FuzzyTrackerConfig& c, std::optional<std::int64_t> prev_t_ns,
                             std::optional<std::int64_t> t_ns);

class FuzzyTracker {
 public:
  explicit FuzzyTracker(const FuzzyTrackerConfig& config) : cfg_(config) {}
  TrackingCommand Update(const PlannedPath& path, const VehiclePose2d& pose);
  void Reset() {
    have_hint_ = false;
    last_steer_rad_ = 0;
    last_t_ns_.reset();
  }
  /// The front-wheel angle of the last Update (rad, + = left).
  double last_steer_rad() const { return last_steer_rad_; }

 private:
  FuzzyTrackerConfig cfg_;
  std::size_t hint_ = 0;
  bool have_hint_ = false;
  double last_steer_rad_ = 0;
  std::optional<std::int64_t> last_t_ns_;  ///< the previous Update's solution time
};

}  // namespace hil::estimator::guidance

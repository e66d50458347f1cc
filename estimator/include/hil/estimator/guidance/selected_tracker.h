#pragma once
/// @file
/// The path tracker a guidance daemon runs, chosen at start-up: pure pursuit (path_tracker.h) or
/// paper 003's self-adjusting fuzzy tracker (fuzzy_tracker.h). On a front-steered platform
/// (wheelbase > 0) both answer with a curvature the push rod can reach (|δ| ≤ max steer), so the
/// baseline and the fuzzy controller command the same vehicle within the same limits. One Update
/// per solution, no allocation.

#include <optional>
#include <string_view>

#include "hil/estimator/guidance/fuzzy_tracker.h"
#include "hil/estimator/guidance/path_tracker.h"
#include "hil/estimator/guidance/vehicle.h"

namespace hil::estimator::guidance {

enum class TrackerKind { kPurePursuit, kFuzzy };

/// "pure_pursuit" or "fuzzy"; nullopt for anything else.
std::optional<TrackerKind> ParseTrackerKind(std::string_view name);

struct SelectedTrackerConfig {
  TrackerKind kind = TrackerKind::kPurePursuit;
  PurePursuitConfig pure_pursuit;
  FuzzyTrackerConfig fuzzy;
  /// The front-steered platform's wheelbase (m); 0: no steering limit (a differential-drive base).
  double wheelbase_m = 0;
  double max_steer_deg = 32;  ///< the platform's steering range (paper 003's push rod: ±32°)
};

class SelectedTracker {
 public:
  explicit SelectedTracker(const SelectedTrackerConfig& config);
  TrackingCommand Update(const PlannedPath& path, const VehiclePose2d& pose);
  TrackerKind kind() const { return cfg_.kind; }

 private:
  SelectedTrackerConfig cfg_;
  PurePursuit pure_pursuit_;
  FuzzyTracker fuzzy_;
  FrontSteeredPlatform platform_;
};

}  // namespace hil::estimator::guidance

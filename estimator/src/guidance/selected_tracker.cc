#include "hil/estimator/guidance/selected_tracker.h"

#include <numbers>

namespace hil::estimator::guidance {
namespace {

FuzzyTrackerConfig WithPlatform(FuzzyTrackerConfig f, const SelectedTrackerConfig& c) {
  if (c.wheelbase_m > 0) {
    f.wheelbase_m = c.wheelbase_m;
    f.alpha_max_deg = c.max_steer_deg;
  }
  return f;
}

}  // namespace

std::optional<TrackerKind> ParseTrackerKind(std::string_view name) {
  if (name == "pure_pursuit") return TrackerKind::kPurePursuit;
  if (name == "fuzzy") return TrackerKind::kFuzzy;
  return std::nullopt;
}

SelectedTracker::SelectedTracker(const SelectedTrackerConfig& config)
    : cfg_(config),
      pure_pursuit_(config.pure_pursuit),
      fuzzy_(WithPlatform(config.fuzzy, config)),
      platform_{config.wheelbase_m, config.max_steer_deg * std::numbers::pi / 180.0} {}

TrackingCommand SelectedTracker::Update(const PlannedPath& path, const VehiclePose2d& pose) {
  TrackingCommand c = cfg_.kind == TrackerKind::kFuzzy ? fuzzy_.Update(path, pose)
                                                       : pure_pursuit_.Update(path, pose);
  if (cfg_.wheelbase_m > 0) c.curvature_left_per_m = platform_.Reachable(c.curvature_left_per_m);
  return c;
}

}  // namespace hil::estimator::guidance

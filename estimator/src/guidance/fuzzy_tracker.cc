#include "hil/estimator/guidance/fuzzy_tracker.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hil::estimator::guidance {
namespace {
constexpr double kDegPerRad = 180.0 / std::numbers::pi;
}  // namespace

double FuzzyWeight(const FuzzyTrackerConfig& c, double d_m) {
  const double n = c.weight_k * std::pow(std::fabs(d_m / c.weight_m_m), c.weight_p);
  const double n_max = std::clamp(c.weight_n_max, 0.0, 1.0);
  return std::isfinite(n) ? std::clamp(n, 0.0, n_max) : n_max;
}

double FuzzySteerAngle_rad(const FuzzyTrackerConfig& c, double d_m, double theta_rad) {
  const double s = c.domain_s;
  const double big_d = std::clamp(s / c.d_range_m * d_m, -s, s);
  const double big_theta = std::clamp(s / c.theta_range_deg * theta_rad * kDegPerRad, -s, s);
  const double n = FuzzyWeight(c, d_m);
  double a = n * -big_d + (1.0 - n) * big_theta;
  if (c.quantise_levels) a = std::round(a);
  const double alpha_deg = std::clamp(c.k_alpha_deg * a, -c.alpha_max_deg, c.alpha_max_deg);
  return alpha_deg / kDegPerRad;
}

double FuzzyUpdateInterval_s(const FuzzyTrackerConfig& c, std::optional<std::int64_t> prev_t_ns,
                             std::optional<std::int64_t> t_ns) {
  constexpr std::int64_t kDay_ns = 86'400'000'000'000;
  if (!prev_t_ns || !t_ns) return c.fallback_period_s;
  const std::int64_t dt_ns = ((*t_ns - *prev_t_ns) % kDay_ns + kDay_ns) % kDay_ns;
  if (dt_ns >= kDay_ns / 2) return c.fallback_period_s;
  return static_cast<double>(dt_ns) * 1e-9;
}

TrackingCommand FuzzyTracker::Update(const PlannedPath& path, const VehiclePose2d& pose) {
  if (path.vertex_count() < 2) return {};
  const PathProjection foot = have_hint_ ? path.Project(pose.p_EN_m, hint_, cfg_.search_window_m)
                                         : path.Project(pose.p_EN_m);
  hint_ = foot.edge;
  have_hint_ = true;
  TrackingCommand c;
  c.cross_track_m = foot.cross_track_m;
  double tracking_yaw_rad = foot.path_yaw_rad;
  if (cfg_.heading_preview_m > 0) {
    const Eigen::Vector2d goal = path.PointAt(foot.s_m + cfg_.heading_preview_m, foot.edge);
    const Eigen::Vector2d to_goal = goal - pose.p_EN_m;
    if (to_goal.norm() > 1e-6) tracking_yaw_rad = std::atan2(to_goal.y(), to_goal.x());
  }
  c.heading_error_rad = WrapPi(foot.path_yaw_rad - pose.yaw_rad);
  const double theta_rad = WrapPi(tracking_yaw_rad - pose.yaw_rad);
  c.s_m = foot.s_m;
  c.end_of_path = foot.s_m >= path.length_m() - 1e-6;
  double steer_rad = FuzzySteerAngle_rad(cfg_, c.cross_track_m, theta_rad);
  if (cfg_.steer_rate_limit_deg_s > 0) {
    const double dt_s = FuzzyUpdateInterval_s(cfg_, last_t_ns_, pose.t_ns);
    const double step_rad = cfg_.steer_rate_limit_deg_s / kDegPerRad * dt_s;
    steer_rad = std::clamp(steer_rad, last_steer_rad_ - step_rad, last_steer_rad_ + step_rad);
  }
  last_t_ns_ = pose.t_ns;
  last_steer_rad_ = steer_rad;
  c.curvature_left_per_m = std::tan(last_steer_rad_) / cfg_.wheelbase_m;
  return c;
}

}  // namespace hil::estimator::guidance

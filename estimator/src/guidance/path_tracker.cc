#include "hil/estimator/guidance/path_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace hil::estimator::guidance {
namespace {

PathProjection ProjectWithHint(const PlannedPath& path, const Eigen::Vector2d& p, std::size_t& hint,
                               bool& have_hint, double window_m) {
  const PathProjection f = have_hint ? path.Project(p, hint, window_m) : path.Project(p);
  hint = f.edge;
  have_hint = true;
  return f;
}

TrackingCommand Describe(const PathProjection& foot, const PlannedPath& path,
                         const VehiclePose2d& pose) {
  TrackingCommand c;
  c.cross_track_m = foot.cross_track_m;
  c.heading_error_rad = WrapPi(foot.path_yaw_rad - pose.yaw_rad);
  c.s_m = foot.s_m;
  c.end_of_path = foot.s_m >= path.length_m() - 1e-6;
  return c;
}

}  // namespace

double WrapPi(double a) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  a = std::fmod(a, kTwoPi);
  if (a > std::numbers::pi) a -= kTwoPi;
  if (a <= -std::numbers::pi) a += kTwoPi;
  return a;
}

TrackingCommand PurePursuit::Update(const PlannedPath& path, const VehiclePose2d& pose) {
  if (path.vertex_count() < 2) return {};
  const PathProjection foot =
      ProjectWithHint(path, pose.p_EN_m, hint_, have_hint_, cfg_.search_window_m);
  TrackingCommand c = Describe(foot, path, pose);
  const double ld = std::clamp(cfg_.lookahead_m + cfg_.lookahead_gain_s * std::fabs(pose.speed_mps),
                               cfg_.min_lookahead_m, cfg_.max_lookahead_m);
  const Eigen::Vector2d goal = path.PointAt(foot.s_m + ld, foot.edge);
  const Eigen::Vector2d r = goal - pose.p_EN_m;
  const double d2 = r.squaredNorm();
  if (d2 < 1e-12) return c;
  // Goal in the vehicle frame (x forward, y left): κ = 2 y / D².
  const double cy = std::cos(pose.yaw_rad), sy = std::sin(pose.yaw_rad);
  const double lateral = -sy * r.x() + cy * r.y();
  c.curvature_left_per_m = 2.0 * lateral / d2;
  return c;
}

TrackingCommand Stanley::Update(const PlannedPath& path, const VehiclePose2d& pose) {
  if (path.vertex_count() < 2) return {};
  const Eigen::Vector2d heading(std::cos(pose.yaw_rad), std::sin(pose.yaw_rad));
  const Eigen::Vector2d front = pose.p_EN_m + cfg_.wheelbase_m * heading;
  const PathProjection f = ProjectWithHint(path, front, hint_, have_hint_, cfg_.search_window_m);
  const PathProjection ref =
      path.Project(pose.p_EN_m, f.edge, cfg_.search_window_m + cfg_.wheelbase_m);
  TrackingCommand c = Describe(ref, path, pose);
  c.end_of_path = f.s_m >= path.length_m() - 1e-6;
  const double psi_e = WrapPi(f.path_yaw_rad - pose.yaw_rad);
  const double v = std::fabs(pose.speed_mps);
  const double delta =
      std::clamp(psi_e + std::atan(-cfg_.gain * f.cross_track_m / (cfg_.softening_mps + v)),
                 -cfg_.max_steer_rad, cfg_.max_steer_rad);
  c.curvature_left_per_m = std::tan(delta) / cfg_.wheelbase_m;
  return c;
}

}  // namespace hil::estimator::guidance

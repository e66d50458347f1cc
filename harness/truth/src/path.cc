#include "hil/truth/path.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "hil/firmware_emu/angles.h"

namespace hil::truth {
namespace {

Eigen::Vector2d Rotate(const Eigen::Vector2d& v, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}
}  // namespace

Eigen::Vector2d DirectionOfHeading(double heading_deg) {
  return {std::sin(heading_deg * kDeg), std::cos(heading_deg * kDeg)};
}

Path::Path(std::vector<PathVertex> vertices) : v_(std::move(vertices)) {
  if (v_.size() < 2) throw std::invalid_argument("a path needs at least 2 vertices");
  s_.push_back(0);
  for (std::size_t i = 0; i + 1 < v_.size(); ++i) {
    const Eigen::Vector2d d = v_[i + 1].p_N_m - v_[i].p_N_m;
    const double len = d.norm();
    if (!(len > 1e-6))
      throw std::invalid_argument("path vertices " + std::to_string(i) + " and " +
                                  std::to_string(i + 1) + " coincide");
    u_.push_back(d / len);
    s_.push_back(s_.back() + len);
  }
  // the bounding circles of runs of interior segments (the end segments extend without limit)
  if (u_.size() > 2)
    blocks_ = BoundSegmentRuns(1, u_.size() - 1, kBlockSegments,
                               [this](std::size_t j) { return v_[j].p_N_m; });
}

Eigen::Vector2d Path::PointAt(double s) const {
  if (s <= 0) return v_.front().p_N_m + s * u_.front();
  if (s >= s_.back()) return v_.back().p_N_m + (s - s_.back()) * u_.back();
  // binary search for the segment holding s
  std::size_t lo = 0, hi = v_.size() - 1;
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (s_[mid] <= s ? lo : hi) = mid;
  }
  return v_[lo].p_N_m + (s - s_[lo]) * u_[lo];
}

double Path::AlongOnSegment(std::size_t i, const Eigen::Vector2d& p) const {
  return s_[i] + (p - v_[i].p_N_m).dot(u_[i]);
}

void Path::ProjectOnSegment(std::size_t i, const Eigen::Vector2d& p, double& best_d2,
                            PathProjection& best) const {
  const Eigen::Vector2d r = p - v_[i].p_N_m;
  const double len = s_[i + 1] - s_[i];
  // the end segments extend without limit, like the follower's view of the path
  double a = r.dot(u_[i]);
  if (i > 0) a = std::max(a, 0.0);
  if (i + 1 < u_.size()) a = std::min(a, len);
  const Eigen::Vector2d off = r - a * u_[i];
  const double d2 = off.squaredNorm();
  if (d2 < best_d2) {
    best_d2 = d2;
    best.segment = i;
    best.along_m = s_[i] + a;
    const double cross = u_[i].x() * r.y() - u_[i].y() * r.x();  // u × r, left positive
    best.cross_track_m = (cross >= 0 ? 1.0 : -1.0) * std::sqrt(d2);
  }
}

PathProjection Path::Project(const Eigen::Vector2d& p) const {
  // the segments in order, as a full scan takes them (ties go to the first); a run of segments
  // is skipped only when even its circle lies beyond the best distance, with a margin far above
  // the rounding of either distance
  constexpr double kMargin_m = 1e-6;
  PathProjection best;
  double best_d2 = std::numeric_limits<double>::infinity();
  ProjectOnSegment(0, p, best_d2, best);
  for (const SegmentRun& b : blocks_) {
    const double gap_m = (p - b.centre).norm() - b.radius_m - kMargin_m;
    if (gap_m > 0 && gap_m * gap_m > best_d2) continue;
    for (std::size_t i = b.first; i < b.end; ++i) ProjectOnSegment(i, p, best_d2, best);
  }
  if (u_.size() > 1) ProjectOnSegment(u_.size() - 1, p, best_d2, best);
  return best;
}

double CrossTrackError(const Path& path, const Eigen::Vector3d& p_N_m) {
  return path.Project(p_N_m.head<2>()).cross_track_m;
}

Path MakeAbLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double extend_m) {
  const Eigen::Vector2d u = (b - a).normalized();
  std::vector<PathVertex> v{{a, {}, 0}, {b, {}, 0}};
  if (extend_m > 0) v.push_back({b + extend_m * u, {}, 0});
  return Path(std::move(v));
}

Path MakeRectangle(const Eigen::Vector2d& start, double width_m, double height_m,
                   double heading_deg, bool clockwise, int laps) {
  const Eigen::Vector2d u = DirectionOfHeading(heading_deg);
  const Eigen::Vector2d side =
      clockwise ? Eigen::Vector2d(u.y(), -u.x()) : Eigen::Vector2d(-u.y(), u.x());
  const Eigen::Vector2d corners[4] = {
      start, start + height_m * u, start + height_m * u + width_m * side, start + width_m * side};
  std::vector<PathVertex> v{{start, {}, 0}};
  for (int lap = 0; lap < laps; ++lap) {
    for (int k = 1; k <= 4; ++k) v.push_back({corners[k % 4], {}, 0});
  }
  return Path(std::move(v));
}

Path MakeBoustrophedon(const BoustrophedonSpec& b) {
  if (b.row_spacing_m < 2 * b.turn_radius_m - 1e-9) {
    throw std::invalid_argument("row spacing must be at least twice the turn radius");
  }
  std::vector<PathVertex> v;
  const Eigen::Vector2d u0 = DirectionOfHeading(b.heading_deg);
  // the side the next row lies on
  const Eigen::Vector2d side =
      b.first_turn_right ? Eigen::Vector2d(u0.y(), -u0.x()) : Eigen::Vector2d(-u0.y(), u0.x());
  const int arc_points = std::max(2, static_cast<int>(std::ceil(90.0 / b.arc_step_deg)));
  for (int row = 0; row < b.rows; ++row) {
    const Eigen::Vector2d u = row % 2 == 0 ? u0 : Eigen::Vector2d(-u0);
    const Eigen::Vector2d a =
        b.start_p_N_m + static_cast<double>(row) * b.row_spacing_m * side +
        (row % 2 == 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(b.row_length_m * u0));
    const Eigen::Vector2d e = a + b.row_length_m * u;
    if (row == 0) v.push_back({a, {}, 0});
    v.push_back({e, b.turn_speed_mps, 0});
    if (row + 1 == b.rows) break;
    // headland turn towards `side`: quarter arc, straight across, quarter arc
    const double turn_sign =
        (u.x() * side.y() - u.y() * side.x()) > 0 ? 1.0 : -1.0;  // +1: left turn
    const double r = b.turn_radius_m;
    const Eigen::Vector2d c1 = e + r * side;
    for (int k = 1; k <= arc_points; ++k) {
      const double ang = turn_sign * (std::numbers::pi / 2) * k / arc_points;
      v.push_back({c1 + Rotate(-r * side, ang), b.turn_speed_mps, 0});
    }
    const double straight = b.row_spacing_m - 2 * r;
    const Eigen::Vector2d p2 = v.back().p_N_m + straight * side;
    if (straight > 1e-3) v.push_back({p2, b.turn_speed_mps, 0});
    const Eigen::Vector2d c2 = p2 - r * u;
    for (int k = 1; k <= arc_points; ++k) {
      const double ang = turn_sign * (std::numbers::pi / 2) * k / arc_points;
      v.push_back({c2 + Rotate(r * u, ang),
                   k == arc_points ? std::optional<double>{} : b.turn_speed_mps, 0});
    }
  }
  return Path(std::move(v));
}

Path MakeCircle(const Eigen::Vector2d& centre, double radius_m, double start_bearing_deg,
                bool counter_clockwise, int laps, int points_per_lap) {
  std::vector<PathVertex> v;
  const Eigen::Vector2d r0 = radius_m * DirectionOfHeading(start_bearing_deg);
  const double sign = counter_clockwise ? 1.0 : -1.0;
  for (int k = 0; k <= laps * points_per_lap; ++k) {
    v.push_back({centre + Rotate(r0, sign * 2 * std::numbers::pi * k / points_per_lap), {}, 0});
  }
  return Path(std::move(v));
}

}  // namespace hil::truth

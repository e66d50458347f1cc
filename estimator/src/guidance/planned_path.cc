#include "hil/estimator/guidance/planned_path.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hil::estimator::guidance {

void PlannedPath::Append(const Eigen::Vector2d& p_EN_m, SegmentKind kind, int segment) {
  if (!p_.empty() && (p_EN_m - p_.back()).norm() < 1e-9) {
    kind_.back() = kind;
    segment_.back() = segment;
    return;
  }
  s_.push_back(p_.empty() ? 0.0 : s_.back() + (p_EN_m - p_.back()).norm());
  p_.push_back(p_EN_m);
  kind_.push_back(kind);
  segment_.push_back(segment);
}

PathProjection PlannedPath::ProjectOnEdge(const Eigen::Vector2d& p, std::size_t i,
                                          bool extend) const {
  const Eigen::Vector2d a = p_[i];
  const Eigen::Vector2d d = p_[i + 1] - a;
  const double len = s_[i + 1] - s_[i];
  const Eigen::Vector2d u = d / len;
  double along = (p - a).dot(u);
  const bool first = extend && i == 0, last = extend && i + 2 == p_.size();
  if (!first) along = std::max(along, 0.0);  // only the path's ends extend beyond their vertex
  if (!last) along = std::min(along, len);
  PathProjection out;
  out.edge = i;
  out.s_m = s_[i] + along;
  out.p_EN_m = a + along * u;
  out.tangent_EN = u;
  const Eigen::Vector2d r = p - out.p_EN_m;
  out.cross_track_m = u.x() * r.y() - u.y() * r.x();
  out.path_yaw_rad = std::atan2(u.y(), u.x());
  return out;
}

PathProjection PlannedPath::Project(const Eigen::Vector2d& p_EN_m) const {
  return Project(p_EN_m, 0, std::numeric_limits<double>::infinity());
}

PathProjection PlannedPath::Project(const Eigen::Vector2d& p_EN_m, std::size_t hint,
                                    double window_m) const {
  PathProjection best;
  if (p_.size() < 2) return best;
  hint = std::min(hint, p_.size() - 2);
  // Ties within 1 µm go to the earlier edge (a path that passes a place twice, e.g. a circle of
  // several laps, is entered on its first pass).
  double best_d = std::numeric_limits<double>::infinity();
  std::size_t lo = hint;
  while (lo > 0 && s_[hint] - s_[lo] < window_m) --lo;
  for (std::size_t i = lo; i + 1 < p_.size(); ++i) {
    if (s_[i] - s_[hint + 1] > window_m) break;
    const PathProjection c = ProjectOnEdge(p_EN_m, i, false);
    const double d = (p_EN_m - c.p_EN_m).norm();
    if (d < best_d - 1e-6) {
      best_d = d;
      best = c;
    }
  }
  // Past an end (the foot clamped there), the path continues straight along its end edge.
  if (best.edge == 0 && best.s_m <= s_[0]) return ProjectOnEdge(p_EN_m, 0, true);
  if (best.edge + 2 == p_.size() && best.s_m >= s_.back())
    return ProjectOnEdge(p_EN_m, best.edge, true);
  return best;
}

Eigen::Vector2d PlannedPath::PointAt(double s_m, std::size_t hint, std::size_t* edge_out) const {
  if (p_.size() < 2) return p_.empty() ? Eigen::Vector2d(0, 0) : p_[0];
  std::size_t i = std::min(hint, p_.size() - 2);
  while (i > 0 && s_[i] > s_m) --i;
  while (i + 2 < p_.size() && s_[i + 1] < s_m) ++i;
  if (edge_out) *edge_out = i;
  const Eigen::Vector2d u = (p_[i + 1] - p_[i]) / (s_[i + 1] - s_[i]);
  return p_[i] + (s_m - s_[i]) * u;
}

}  // namespace hil::estimator::guidance

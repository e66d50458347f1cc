#include "hil/harness/eval/cross_track.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hil::harness {

PlannedPath::PlannedPath(std::vector<Eigen::Vector2d> vertices_enu_m)
    : vertices_(std::move(vertices_enu_m)) {
  if (vertices_.size() < 2)
    throw std::invalid_argument("a planned path needs at least two vertices");
  blocks_ = truth::BoundSegmentRuns(0, vertices_.size() - 1, kBlockSegments,
                                    [this](std::size_t j) { return vertices_[j]; });
}

void PlannedPath::CrossTrackOnSegment(std::size_t i, const Eigen::Vector2d& p, double& best_d,
                                      double& best_signed) const {
  const Eigen::Vector2d a = vertices_[i];
  const Eigen::Vector2d ab = vertices_[i + 1] - a;
  const double len2 = ab.squaredNorm();
  if (len2 <= 0) return;
  const double f = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  const Eigen::Vector2d q = a + f * ab;
  const double d = (p - q).norm();
  if (d < best_d) {
    best_d = d;
    // left of travel: cross product of direction and offset is positive
    const double cross = ab.x() * (p - a).y() - ab.y() * (p - a).x();
    best_signed = cross >= 0 ? d : -d;
  }
}

double PlannedPath::CrossTrack(const Eigen::Vector2d& p) const {
  // the segments in order, as a full scan takes them; a run is skipped only when even its circle
  // lies beyond the best distance, with a margin far above the rounding of either distance
  constexpr double kMargin_m = 1e-6;
  double best_d = std::numeric_limits<double>::infinity();
  double best_signed = 0;
  for (const truth::SegmentRun& b : blocks_) {
    if ((p - b.centre).norm() - b.radius_m - kMargin_m > best_d) continue;
    for (std::size_t i = b.first; i < b.end; ++i) CrossTrackOnSegment(i, p, best_d, best_signed);
  }
  return best_signed;
}

PlannedPath PlannedPathOf(const truth::TruthConfig& c, double duration_s) {
  if (c.path) {
    // a path-following scenario: the planned path is the followed polyline itself
    std::vector<Eigen::Vector2d> v;
    for (const truth::PathVertex& pv : c.path->vertices()) v.push_back(pv.p_N_m);
    return PlannedPath(std::move(v));
  }
  const Eigen::Vector2d start = c.start_p_N_m.value_or(Eigen::Vector2d::Zero());
  const double psi = c.heading_deg.value_or(0.0) * M_PI / 180.0;  // clockwise from north
  const Eigen::Vector2d dir(std::sin(psi), std::cos(psi));
  const double length_m = std::max(1.0, c.speed_mps * duration_s * 1.2 + 10.0);
  std::vector<Eigen::Vector2d> v;
  if (std::abs(c.steer_deg) < 1e-9) {
    v = {start - 10.0 * dir, start + length_m * dir};
    return PlannedPath(std::move(v));
  }
  // constant steering: a circle of radius R, turning left for positive steer
  const double radius_m = c.vehicle.wheelbase_m / std::tan(std::abs(c.steer_deg) * M_PI / 180.0);
  const double side = c.steer_deg > 0 ? 1.0 : -1.0;
  const Eigen::Vector2d left(-dir.y(), dir.x());
  const Eigen::Vector2d centre = start + side * radius_m * left;
  const double sweep = std::min(2.0 * M_PI, length_m / radius_m);
  const int n = std::max(16, static_cast<int>(sweep / 0.002));  // chord error ≤ R·2e-6·… negligible
  const Eigen::Vector2d r0 = start - centre;
  for (int i = 0; i <= n; ++i) {
    const double a = side * sweep * i / n;
    v.emplace_back(centre + Eigen::Vector2d(r0.x() * std::cos(a) - r0.y() * std::sin(a),
                                            r0.x() * std::sin(a) + r0.y() * std::cos(a)));
  }
  return PlannedPath(std::move(v));
}

void AddCrossTrack(std::vector<ErrorSample>& errors, const PlannedPath& path) {
  for (ErrorSample& e : errors) {
    e.xte_m = path.CrossTrack(e.est_enu_m.head<2>()) - path.CrossTrack(e.truth_enu_m.head<2>());
  }
}

}  // namespace hil::harness

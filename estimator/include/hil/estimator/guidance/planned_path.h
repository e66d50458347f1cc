#pragma once
/// @file
/// A planned path in the local east-north plane (metres from the scenario's origin), as read from
/// a planned-path file (vectors/paths/README.md): vertices joined by straight edges, each edge
/// tagged with the segment it belongs to (a row, a headland turn, a side of a rectangle) and that
/// segment's kind. Arcs are stored as chords no longer than the file's `step_m`.
///
/// The path is built once (allocation happens there); every query afterwards is allocation-free
/// and, given the previous answer as a hint, costs a few edges.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace hil::estimator::guidance {

enum class SegmentKind : std::uint8_t { kStraight, kTurn };

/// The foot of a point on the path.
struct PathProjection {
  std::size_t edge = 0;              ///< index of the edge's first vertex
  double s_m = 0;                    ///< arc length of the foot from the path's start
  Eigen::Vector2d p_EN_m{0, 0};      ///< the foot
  Eigen::Vector2d tangent_EN{1, 0};  ///< unit direction of travel at the foot
  double cross_track_m = 0;          ///< signed distance of the point from the path, + = left of it
  double path_yaw_rad = 0;           ///< direction of travel, ENU (0 = east, + counter-clockwise)
};

class PlannedPath {
 public:
  /// Appends a vertex; `kind` and `segment` describe the edge that starts at this vertex.
  /// Consecutive duplicate vertices are dropped.
  void Append(const Eigen::Vector2d& p_EN_m, SegmentKind kind, int segment);

  std::size_t vertex_count() const { return p_.size(); }
  const Eigen::Vector2d& vertex(std::size_t i) const { return p_[i]; }
  double s_at_vertex_m(std::size_t i) const { return s_[i]; }
  SegmentKind edge_kind(std::size_t i) const { return kind_[i]; }
  int edge_segment(std::size_t i) const { return segment_[i]; }
  double length_m() const { return s_.empty() ? 0.0 : s_.back(); }
  int segment_count() const { return segment_.empty() ? 0 : segment_.back() + 1; }

  /// Nearest foot of `p` on the path (of feet within 1 µm of each other, the earliest); a point
  /// beyond an end, whose nearest foot is that end, projects onto the end edge's extension. With
  /// `hint` (the previous projection's edge) only edges up to `window_m` of arc length around it
  /// are searched; without, all edges.
  PathProjection Project(const Eigen::Vector2d& p_EN_m) const;
  PathProjection Project(const Eigen::Vector2d& p_EN_m, std::size_t hint, double window_m) const;
  /// The point at arc length `s_m`, searching forward from edge `hint`; beyond the ends the path
  /// continues straight along its first / last edge.
  Eigen::Vector2d PointAt(double s_m, std::size_t hint, std::size_t* edge_out = nullptr) const;

 private:
  PathProjection ProjectOnEdge(const Eigen::Vector2d& p, std::size_t i, bool extend) const;

  std::vector<Eigen::Vector2d> p_;
  std::vector<double> s_;
  std::vector<SegmentKind> kind_;
  std::vector<int> segment_;
};

}  // namespace hil::estimator::guidance

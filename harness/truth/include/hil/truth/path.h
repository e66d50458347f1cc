#pragma once
/// @file
/// Planned paths in the local ENU frame N: polylines with per-vertex speeds and stops, builders
/// for the scenario shapes (AB line, waypoints, rectangle, boustrophedon field pattern, circle),
/// and the cross-track error of a point against the path (used by the evaluator).

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "hil/truth/segment_runs.h"

namespace hil::truth {

/// One vertex of a planned path.
struct PathVertex {
  Eigen::Vector2d p_N_m{0, 0};      ///< ENU position (m)
  std::optional<double> speed_mps;  ///< speed on the segment that starts here (default: nominal)
  double stop_s = 0;                ///< stop at this vertex for this long (0: drive through)
};

/// Where a point is relative to a path.
struct PathProjection {
  double cross_track_m = 0;  ///< signed distance to the nearest segment, left of the path positive
  double along_m = 0;        ///< arc length of the nearest path point from the start
  std::size_t segment = 0;   ///< index of the nearest segment
};

/// A polyline path; segment i runs from vertex i to vertex i + 1. Beyond its last vertex the path
/// continues straight (the look-ahead of a follower may run past the end).
class Path {
 public:
  Path() = default;
  /// @throws std::invalid_argument with fewer than 2 vertices or a zero-length segment.
  explicit Path(std::vector<PathVertex> vertices);

  const std::vector<PathVertex>& vertices() const { return v_; }
  std::size_t segments() const { return v_.empty() ? 0 : v_.size() - 1; }
  double length_m() const { return s_.empty() ? 0 : s_.back(); }
  /// Arc length at vertex i.
  double s_at_vertex(std::size_t i) const { return s_[i]; }
  /// Unit direction of segment i.
  const Eigen::Vector2d& direction(std::size_t i) const { return u_[i]; }
  /// The point at arc length s (before the start and past the end: on the extended end segments).
  Eigen::Vector2d PointAt(double s_m) const;
  /// Arc length of the projection of p onto segment i's line (may lie outside the segment).
  double AlongOnSegment(std::size_t i, const Eigen::Vector2d& p_N_m) const;
  /// The nearest point of the whole path to p: cross-track error (left positive) and along-track.
  PathProjection Project(const Eigen::Vector2d& p_N_m) const;

 private:
  std::vector<PathVertex> v_;
  std::vector<double> s_;           // arc length at each vertex
  std::vector<Eigen::Vector2d> u_;  // unit direction of each segment
  /// Project's pruning: the segments between the two end segments in runs of kBlockSegments
  /// (segment_runs.h); a run whose circle lies farther than the nearest segment found so far
  /// cannot hold a nearer one and is skipped (the result is the full scan's).
  static constexpr std::size_t kBlockSegments = 8;
  std::vector<SegmentRun> blocks_;
  /// Project's step for segment i: a nearer point than `best_d2` (squared distance) updates both.
  void ProjectOnSegment(std::size_t i, const Eigen::Vector2d& p, double& best_d2,
                        PathProjection& best) const;
};

/// Cross-track error (m, left of the path positive) of an ENU point against a path.
double CrossTrackError(const Path& path, const Eigen::Vector3d& p_N_m);

/// Direction of a heading given in degrees clockwise from north, as an ENU unit vector.
Eigen::Vector2d DirectionOfHeading(double heading_deg);

/// A straight line from a along the direction to b, extended `extend_m` past b.
Path MakeAbLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double extend_m);
/// A w × h rectangle from its corner `start` along `heading_deg`, turning clockwise (right) or
/// counter-clockwise, repeated `laps` times and closed at the start.
Path MakeRectangle(const Eigen::Vector2d& start, double width_m, double height_m,
                   double heading_deg, bool clockwise, int laps);

/// The boustrophedon (back-and-forth) field pattern.
struct BoustrophedonSpec {
  Eigen::Vector2d start_p_N_m{0, 0};  ///< start of the first row
  double heading_deg = 0;             ///< direction of the first row, clockwise from north
  double row_length_m = 100;
  double row_spacing_m = 7.5;
  int rows = 4;
  double turn_radius_m = 3.5;  ///< headland turns: quarter arc, straight, quarter arc
  bool first_turn_right = true;
  std::optional<double> turn_speed_mps;  ///< speed through the headland turns
  double arc_step_deg = 5;               ///< polyline resolution of the arcs
};
/// @throws std::invalid_argument when row_spacing < 2 × turn_radius.
Path MakeBoustrophedon(const BoustrophedonSpec& b);
/// A circle of `radius_m` about `centre`, starting at the point that lies at bearing
/// `start_bearing_deg` (clockwise from north) from the centre, travelling counter-clockwise (left
/// turn) or clockwise, `laps` times, as a polygon with `points_per_lap` vertices.
Path MakeCircle(const Eigen::Vector2d& centre, double radius_m, double start_bearing_deg,
                bool counter_clockwise, int laps, int points_per_lap);

}  // namespace hil::truth

#pragma once
/// @file
/// Cross-track error (XTE) against the planned path, computed the way ISO 12188-2 expects with an
/// interpolated reference path: the path is a polyline; a point's cross-track distance is its
/// signed distance (left of the direction of travel positive) to the nearest point on any segment
/// (not to the nearest vertex, which overestimates XTE between vertices).
///
/// For an estimator, the harness reports the estimate's XTE minus the truth's XTE at the same time
/// of validity: the lateral error guidance would act on.

#include <vector>

#include <Eigen/Core>

#include "hil/harness/eval/evaluator.h"
#include "hil/truth/segment_runs.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

class PlannedPath {
 public:
  /// @pre at least two distinct vertices.
  explicit PlannedPath(std::vector<Eigen::Vector2d> vertices_enu_m);
  /// Signed distance (m) of `p_enu_m` to the polyline, left of travel positive.
  double CrossTrack(const Eigen::Vector2d& p_enu_m) const;
  const std::vector<Eigen::Vector2d>& vertices() const { return vertices_; }

  /// CrossTrack's pruning: runs of kBlockSegments segments, each inside a circle (segment_runs.h);
  /// a run whose circle lies beyond the nearest point found so far is skipped (the result is the
  /// full scan's).
  static constexpr std::size_t kBlockSegments = 8;

 private:
  /// CrossTrack's step for segment i: a nearer point than `best_d` updates both.
  void CrossTrackOnSegment(std::size_t i, const Eigen::Vector2d& p, double& best_d,
                           double& best_signed) const;
  std::vector<Eigen::Vector2d> vertices_;
  std::vector<truth::SegmentRun> blocks_;
};

/// The path the scenario commands: a straight line from the start along the heading, or (constant
/// steering) the circle of radius wheelbase / tan(steer), as a polyline covering `duration_s` of
/// travel plus margin.
PlannedPath PlannedPathOf(const truth::TruthConfig& config, double duration_s);

/// Sets `xte_m` of every sample (estimate XTE minus truth XTE).
void AddCrossTrack(std::vector<ErrorSample>& errors, const PlannedPath& path);

}  // namespace hil::harness

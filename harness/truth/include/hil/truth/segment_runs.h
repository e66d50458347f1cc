#pragma once
/// @file
/// Bounding circles of runs of consecutive polyline segments, for nearest-segment searches that
/// skip a whole run when even its circle lies beyond the nearest point found so far (the truth's
/// Path::Project and the evaluation's PlannedPath::CrossTrack). The result of such a search is the
/// full scan's, as long as the skip test keeps a margin above the distances' rounding.
#include <algorithm>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace hil::truth {

struct SegmentRun {
  std::size_t first = 0, end = 0;  ///< segments [first, end); segment i joins vertices i and i + 1
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius_m = 0;  ///< every vertex of the run lies within this of `centre`
};

/// Runs of at most `run_length` segments covering segments [first, end); `vertex(j)` gives
/// vertex j (ENU, m).
template <typename VertexAt>
std::vector<SegmentRun> BoundSegmentRuns(std::size_t first, std::size_t end, std::size_t run_length,
                                         VertexAt vertex) {
  std::vector<SegmentRun> runs;
  for (std::size_t start = first; start < end; start += run_length) {
    SegmentRun r;
    r.first = start;
    r.end = std::min(start + run_length, end);
    Eigen::Vector2d lo = vertex(start), hi = lo;
    for (std::size_t j = start; j <= r.end; ++j) {
      lo = lo.cwiseMin(vertex(j));
      hi = hi.cwiseMax(vertex(j));
    }
    r.centre = (lo + hi) / 2;
    for (std::size_t j = start; j <= r.end; ++j)
      r.radius_m = std::max(r.radius_m, (vertex(j) - r.centre).norm());
    runs.push_back(r);
  }
  return runs;
}

}  // namespace hil::truth

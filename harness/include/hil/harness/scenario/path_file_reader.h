#pragma once
/// @file
/// The evaluator's own reader of planned-path files (vectors/paths/README.md), independent of the
/// controller's (estimator/guidance/path_file.h): the harness scores the truth against the path
/// the file describes, not against what the controller made of it. It reads every shape: the
/// straight ones (`ab_line`, `polyline`) and those with arcs (`circle`, `rectangle` with rounded
/// corners, `boustrophedon` with headland turns). An arc is built here from its centre and its
/// swept angle, in chords no longer than `step_m` (the same chord rule as the controller's, so
/// both describe the same polyline). Errors name the file, the line and the field (exit 2).

#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hil::harness {

/// A path file the evaluator cannot use.
class PathFileReadError : public std::runtime_error {
 public:
  explicit PathFileReadError(const std::string& what) : std::runtime_error(what) {}
};

/// A path as the evaluator scores it: a polyline, each edge in one segment (a row, a side, a
/// headland turn, a corner), each segment straight or a turn.
struct PathGeometry {
  std::vector<Eigen::Vector2d> vertices;  ///< ENU metres from the scenario's origin
  std::vector<int> edge_segment;          ///< per edge (vertices.size() − 1): its segment
  std::vector<bool> segment_is_turn;      ///< per segment
};

/// The path of a file. @throws PathFileReadError naming file, line and field.
PathGeometry ReadPathGeometry(const std::string& file);

/// The vertices of a path file (ReadPathGeometry(file).vertices).
std::vector<Eigen::Vector2d> ReadPathVertices(const std::string& file);

}  // namespace hil::harness

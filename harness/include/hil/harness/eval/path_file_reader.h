#pragma once
/// @file
/// The evaluator's own reader of planned-path files (vectors/paths/README.md), independent of the
/// controller's (estimator/guidance/path_file.h): the harness scores the truth against the path
/// the file describes, not against what the controller made of it. It reads the straight shapes
/// (`ab_line`, `polyline`); a path with arcs is refused by name. Errors name the file, the line
/// and the field (exit 2).

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

/// The vertices of a path file (ENU metres from the scenario's origin); each edge between two
/// vertices is one straight segment.
std::vector<Eigen::Vector2d> ReadPathVertices(const std::string& file);

}  // namespace hil::harness

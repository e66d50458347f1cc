#pragma once
/// @file
/// The evaluator's own reader of planned-path files (vectors/paths/README.md), independent of the
/// controller's (estimator/guidance/path_file.h): the harness scores the truth against the path
/// the file describes, not against what the controller made of it. It reads the straight shapes
/// (`ab_line`, `polyline`) and the boustrophedon; the other arcs (circle, rectangle) are refused
/// by name. Errors name the file, the line and the field (exit 2).

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

/// A segment of the path: edges [first_edge, end_edge) of the vertex list, a straight (an AB
/// line, a polyline's edge, a boustrophedon's row) or a turn (a headland turn: its arcs as chords).
struct PathSpan {
  std::size_t first_edge = 0, end_edge = 0;
  bool turn = false;
};

/// A path file read: its vertices (ENU metres from the scenario's origin) and its segments.
struct PathFileShape {
  std::vector<Eigen::Vector2d> vertices;
  std::vector<PathSpan> spans;
};

/// Reads a path file: `ab_line`, `polyline` and `boustrophedon` (path_file_boustrophedon.cc; its
/// arcs as chords of at most `step_m`, as the format says).
PathFileShape ReadPathFile(const std::string& file);
/// The vertices of a path file (ReadPathFile(file).vertices).
std::vector<Eigen::Vector2d> ReadPathVertices(const std::string& file);

}  // namespace hil::harness

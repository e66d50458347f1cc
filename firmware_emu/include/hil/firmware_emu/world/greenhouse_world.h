#pragma once
/// @file
/// The greenhouse of paper 001 as a map the sensors ray-cast against, the evaluator measures in
/// and the plots draw: parallel ridges (垄) of a fixed width, height and centre-to-centre spacing,
/// with aisles between them, headlands beyond their ends, and an enclosing wall with posts.
/// Frame: the scenario's ENU frame N (metres). The ridges run along `row_direction_deg`
/// (counter-clockwise from east); ridge i's centre line starts at `first_ridge_start_N_m` shifted
/// i·spacing to the left of that direction and is `ridge_length_m` long. Aisle k lies between
/// ridges k and k+1. The paper gives none of these sizes (seeds_001_003.md A.5, A.14): every value
/// is a scenario parameter; the defaults below are this project's choice (docs in
/// vectors/scenarios/README.md, `greenhouse:` section).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/world/ray_cast.h"

namespace hil::world {

struct GreenhouseConfig {
  Eigen::Vector2d first_ridge_start_N_m = Eigen::Vector2d::Zero();
  double row_direction_deg = 90;  ///< ENU, counter-clockwise from east (90 = rows run north)
  int ridge_count = 4;
  double ridge_width_m = 0.6;
  double ridge_height_m = 0.3;
  double ridge_spacing_m = 1.8;  ///< centre to centre: aisle clearance = spacing − width
  double ridge_length_m = 30;
  double headland_m = 3;       ///< clear ground between the ridge ends and the end walls
  double side_margin_m = 1.5;  ///< between the outer ridges' sides and the side walls
  double wall_height_m = 3;
  double post_spacing_m = 4;  ///< posts along the side walls (0: none)
  double post_size_m = 0.1;   ///< square section
  double post_height_m = 3;
};

/// What a cast ray hit.
enum class ObstacleKind { kRidge, kPost, kWall };

struct WorldHit {
  double range_m = 0;
  ObstacleKind kind = ObstacleKind::kWall;
  int index = 0;                                     ///< ridge, post or wall number
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();  ///< outward, in N
};

/// Reflectivity (0–1, diffuse) of what a beam hits, for the optical sensors' signal strength.
/// Scenario parameters (UNVERIFIED defaults): soil ridges 25 %, galvanised posts 50 %, transparent
/// PE film walls 5 % (most light passes through the film).
struct SurfaceReflectivity {
  double ridge = 0.25, post = 0.5, wall = 0.05;
  double Of(ObstacleKind kind) const {
    return kind == ObstacleKind::kRidge ? ridge : kind == ObstacleKind::kPost ? post : wall;
  }
};

/// A configuration field that makes no sense, and why (the scenario reader names its line).
struct ConfigProblem {
  std::string field, message;
};
/// The first problem of `c`, or none.
std::optional<ConfigProblem> CheckGreenhouse(const GreenhouseConfig& c);

/// Where a point is relative to the aisles.
struct AislePosition {
  int aisle = 0;                ///< nearest aisle, 0 … ridge_count − 2 (0 with a single ridge)
  double along_m = 0;           ///< along the rows from the ridges' start line
  double lateral_m = 0;         ///< left of the aisle's centre line (positive to the left)
  bool between_ridges = false;  ///< along the ridges (0 ≤ along ≤ length)
};

class GreenhouseWorld {
 public:
  /// @throws std::invalid_argument naming the field when CheckGreenhouse finds a problem.
  explicit GreenhouseWorld(const GreenhouseConfig& config);

  /// The nearest obstacle taller than `height_m` on `ray` within `max_range_m`.
  std::optional<WorldHit> Cast(const Ray2& ray, double height_m, double max_range_m) const;
  AislePosition Locate(const Eigen::Vector2d& p_N_m) const;
  /// A point at `along_m` and `lateral_m` (left positive) from aisle k's centre line start.
  Eigen::Vector2d AislePoint(int aisle, double along_m, double lateral_m) const;
  /// Unit vector along the rows, and to their left.
  const Eigen::Vector2d& row_axis() const { return u_; }
  const Eigen::Vector2d& left_axis() const { return v_; }

  const GreenhouseConfig& config() const { return config_; }
  const std::vector<OrientedBox>& ridges() const { return ridges_; }
  const std::vector<OrientedBox>& posts() const { return posts_; }
  /// The four wall segments (end, side, end, side), as corner pairs.
  const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& walls() const { return walls_; }

 private:
  void Build();
  Eigen::Vector2d Map(double along_m, double left_m) const;
  GreenhouseConfig config_;
  Eigen::Vector2d u_, v_;
  std::vector<OrientedBox> ridges_, posts_;
  std::vector<double> ridge_radius_m_, post_radius_m_;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> walls_;
};

}  // namespace hil::world

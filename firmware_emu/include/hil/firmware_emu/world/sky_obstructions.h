#pragma once
/// @file
/// Obstructions of the sky over a field, as a GNSS antenna sees them: tree lines and hedgerows,
/// buildings and greenhouse structures, each a vertical prism (an oriented box footprint in the
/// scenario's ENU frame N, from the ground z = 0 up to its height). Pure geometry of a line of
/// sight from the antenna towards a satellite direction:
///  - what the direct path crosses (its slant length inside each obstacle), and the signal loss
///    that gives with each obstacle's figures (a fixed loss per crossing, a loss per metre inside,
///    a cap; a building is opaque);
///  - the specular reflection off the obstacles' vertical faces that reaches the antenna (image
///    antenna: excess path 2·d·(ŝ·n̂) for a face at distance d with outward normal n̂, valid when
///    the reflection point lies on the face, below its top).
/// The figures of each kind (loss, reflection amplitude) are scenario parameters; their defaults
/// and sources are documented at the scenario section (vectors/scenarios/README.md,
/// `obstructions:`). No allocation in the queries.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/world/ray_cast.h"

namespace hil::world {

enum class SkyObstacleKind { kTreeLine, kBuilding, kGreenhouse };

/// One obstruction: a prism over `footprint` from the ground to `height_m`.
struct SkyObstacle {
  SkyObstacleKind kind = SkyObstacleKind::kTreeLine;
  OrientedBox footprint;            ///< in N (metres)
  double height_m = 0;              ///< top above the ground plane z = 0 of N
  bool opaque = false;              ///< nothing passes (a building)
  double loss_db = 0;               ///< loss of a direct path crossing it (film, glass, steel)
  double loss_db_per_m = 0;         ///< plus this per metre of slant path inside (foliage)
  double max_loss_db = 40;          ///< cap of one crossing's loss
  double reflection_amplitude = 0;  ///< amplitude of the specular reflection off its faces (0–1)
};

/// What the direct path from the antenna towards a direction crosses.
struct LineOfSight {
  bool blocked = false;  ///< an opaque obstacle is in the way
  double loss_db = 0;    ///< summed loss of the crossed obstacles (not opaque ones)
  int crossed = 0;       ///< obstacles crossed
};

/// The strongest specular reflection reaching the antenna from a direction.
struct Reflection {
  double excess_path_m = 0;  ///< reflected path minus direct path
  double amplitude = 0;      ///< relative to an unobstructed direct signal
  int obstacle = 0;          ///< index in the obstruction list
};

/// A configuration field that makes no sense, and why.
struct SkyObstacleProblem {
  std::string field, message;
};
std::optional<SkyObstacleProblem> CheckSkyObstacle(const SkyObstacle& o);

class SkyObstructions {
 public:
  explicit SkyObstructions(std::vector<SkyObstacle> obstacles);
  /// The direct path from the antenna at `p_NA_N_m` towards azimuth `az_rad` (clockwise from
  /// north) and elevation `el_rad`.
  LineOfSight Trace(const Eigen::Vector3d& p_NA_N_m, double az_rad, double el_rad) const;
  /// The strongest reflection off a vertical face (largest amplitude, then shortest excess path).
  std::optional<Reflection> StrongestReflection(const Eigen::Vector3d& p_NA_N_m, double az_rad,
                                                double el_rad) const;
  const std::vector<SkyObstacle>& obstacles() const { return obstacles_; }
  bool empty() const { return obstacles_.empty(); }

 private:
  std::vector<SkyObstacle> obstacles_;
};

}  // namespace hil::world

#pragma once
/// @file
/// The ground under the vehicle: a smooth analytic height field z(e, n) in the local ENU frame N
/// (metres above N's x–y plane, which is the tangent plane at the scenario origin; Earth
/// curvature is not modelled, 0.8 mm at 100 m from the origin). The vehicle's body z axis is the
/// surface normal, so roll and pitch follow the gradient; height, gradient and their time
/// derivatives along a trajectory are exact (Jet2), which keeps the IMU truth consistent.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hil/truth/jet.h"

namespace hil::truth {

/// One sinusoidal undulation of rough ground: A sin(k·p + φ).
struct TerrainWave {
  double amplitude_m = 0;
  Eigen::Vector2d k_radpm{0, 0};  ///< wave vector in ENU (rad/m)
  double phase_rad = 0;
};

/// What the ground looks like.
struct TerrainConfig {
  enum class Type { kFlat, kPlane, kRough };
  Type type = Type::kFlat;
  double height_m = 0;  ///< height of the ground at the origin (all types)
  /// kPlane: slope angle and the direction of steepest ascent (degrees clockwise from north).
  double slope_deg = 0;
  double uphill_heading_deg = 0;
  /// kRough: `waves` undulations with random directions and phases from `seed`, amplitude
  /// `amplitude_m` (each; the sum has an rms of amplitude·√(waves/2)) and wavelengths uniform in
  /// [min_wavelength_m, max_wavelength_m]. A plane slope (above) is added if given.
  double amplitude_m = 0.05;
  double min_wavelength_m = 3;
  double max_wavelength_m = 20;
  int waves = 8;
  std::uint64_t seed = 1;
};

/// The height field made from a TerrainConfig.
class Terrain {
 public:
  explicit Terrain(const TerrainConfig& config);
  /// Height z and gradient (∂z/∂e, ∂z/∂n) at a horizontal position given as jets along a
  /// trajectory; the results carry their exact first and second time derivatives.
  void Evaluate(const Jet2& e, const Jet2& n, Jet2& z, Jet2& dz_de, Jet2& dz_dn) const;
  /// Height (m) at a horizontal ENU position.
  double Height(const Eigen::Vector2d& p_N_m) const;
  /// Gradient (∂z/∂e, ∂z/∂n) at a horizontal ENU position.
  Eigen::Vector2d Gradient(const Eigen::Vector2d& p_N_m) const;
  const std::vector<TerrainWave>& waves() const { return waves_; }

 private:
  double z0_m_ = 0;
  Eigen::Vector2d slope_{0, 0};  ///< constant gradient of the plane part
  std::vector<TerrainWave> waves_;
};

}  // namespace hil::truth

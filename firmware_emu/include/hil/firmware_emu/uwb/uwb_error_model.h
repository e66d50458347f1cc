#pragma once
/// @file
/// The errors of paper 003's UWB positions (seeds_001_003.md §B.5), applied to the truth in the
/// planar frame W (= the scenario's ENU frame N, east and north, metres):
///  - the systematic field of Table 1: the paper corrects with corrected = measured + z(measured)
///    (eq. 8), so the emulator reports the position m that the correction maps back onto the
///    truth, m + z(m) = truth (solved by fixed-point iteration; ≈ truth − z(truth));
///  - a static residual field: what the cubic fit leaves (R² 0.823 / 0.856), a seeded smooth field
///    (a sum of planar cosine waves) of a given 1σ per axis, fixed for a run;
///  - white noise per fix;
///  - NLOS bursts: inside configurable zones (posts, plants) a burst may start at each fix; during
///    it the range to one anchor is longer by a positive bias (seeds_001_003.md §B.4: NLOS).
/// The figures chosen where the paper gives none are in vectors/uwb/README.md.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/mcu/rng.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::uwb {

/// Eq. 7's ten coefficients: z = m3x³ + m2x² + m1x + n3y³ + n2y² + n1y + p3x²y + p2xy² + p1xy + p0.
struct CubicErrorField {
  std::array<double, 10> c{};  ///< m3 m2 m1 n3 n2 n1 p3 p2 p1 p0
  double Evaluate_m(double x_m, double y_m) const;
};

/// Table 1 of paper 003 (z_X and z_Y rows, as printed).
CubicErrorField Paper003FieldX();
CubicErrorField Paper003FieldY();

/// A zone where NLOS bursts happen (a circle in W).
struct NlosZone {
  Eigen::Vector2d centre_W_m = Eigen::Vector2d::Zero();
  double radius_m = 1.0;
  double burst_probability = 0.1;  ///< chance per fix inside the zone that a burst starts
  double burst_duration_s = 1.0;
  double bias_m = 0.3;        ///< mean extra range of the blocked anchor
  double bias_sigma_m = 0.1;  ///< spread of that bias (half-normal added to the mean)
};

struct UwbErrorConfig {
  bool systematic_field = true;                    ///< apply Table 1's field
  Eigen::Vector2d white_sigma_m{0.045, 0.045};     ///< per fix, per axis (1σ)
  Eigen::Vector2d residual_sigma_m{0.035, 0.060};  ///< static residual field (1σ per axis)
  double residual_wavelength_min_m = 4.0, residual_wavelength_max_m = 15.0;
  std::vector<NlosZone> nlos_zones;
};

/// The NLOS state of one fix: the blocked anchor (−1 for none) and its extra range.
struct NlosState {
  int anchor = -1;
  double bias_m = 0;
};

class UwbErrorModel {
 public:
  static constexpr int kResidualWaves = 6;
  UwbErrorModel(const UwbErrorConfig& config, std::uint64_t seed);
  /// The position the module measures for a tag truly at p_W (systematic + residual + white),
  /// before any NLOS effect.
  Eigen::Vector2d Measure(const Eigen::Vector2d& p_W_true_m);
  /// m with m + z(m) = p (the inverse of eq. 8), or p without the systematic field.
  Eigen::Vector2d InverseCorrection(const Eigen::Vector2d& p_W_m) const;
  /// The static residual field at p (m).
  Eigen::Vector2d Residual(const Eigen::Vector2d& p_W_m) const;
  /// Advances the NLOS bursts to time t for a tag at p and returns this fix's state.
  NlosState StepNlos(Time t, const Eigen::Vector2d& p_W_true_m, int anchor_count);

 private:
  struct Wave {
    Eigen::Vector2d k_radpm = Eigen::Vector2d::Zero();
    double phase_rad = 0;
  };
  UwbErrorConfig config_;
  CubicErrorField z_x_ = Paper003FieldX(), z_y_ = Paper003FieldY();
  mcu::Rng rng_;
  std::array<std::array<Wave, kResidualWaves>, 2> waves_{};
  NlosState burst_;
  Time burst_end_{};
};

}  // namespace hil::uwb

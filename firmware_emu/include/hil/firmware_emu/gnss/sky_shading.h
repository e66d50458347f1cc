#pragma once
/// @file
/// @system
/// name: SkyShading (obstructions and multipath of each satellite signal)
/// input: the antenna's truth position in N, each satellite's azimuth and elevation, the world's
///        sky obstructions (tree lines, buildings, greenhouses)
/// output: per satellite: C/N0 change, code and carrier multipath range errors, NLOS flag; from
///         the used satellites, the position error those range errors make and its residuals
/// rate: each navigation epoch
/// @endsystem
///
/// The direct signal loses what the obstructions it crosses take (world::SkyObstructions); the
/// strongest specular reflection off a face adds a copy of relative amplitude α (to the direct
/// one) delayed by the excess path δ, at carrier phase φ = 2π·δ/λ (GPS L1, λ = 0.1903 m). Then:
///  - C/N0 changes by 20·log10|a_d + a_r·e^{jφ}| (a_d: direct amplitude after the loss, a_r the
///    reflection's): fading that follows the geometry (it turns fast when the antenna moves
///    towards the face, slowly when it stands);
///  - code error (two-path model of a DLL, Braasch 1996, in Parkinson & Spilker, "GPS: Theory and
///    Applications" vol. I ch. 14): α·δc·cos φ / (1 + α·cos φ), δc = min(δ, correlator half
///    spacing), α capped at 0.95 (deeper fades put C/N0 below the tracking thresholds);
///  - carrier error: (λ/2π)·atan2(α·sin φ, 1 + α·cos φ), at most λ/4 ≈ 4.8 cm;
///  - a direct path that is blocked (opaque) or weaker than the reflection (α ≥ 1) leaves the
///    reflection alone: non-line-of-sight, code and carrier error = δ (a positive bias).
/// Satellites below `track_min_dbhz` are not tracked, below `nav_min_dbhz` not used.
/// The position error of the used satellites' range errors is the least-squares solution with
/// the geometry ComputeDops uses (unweighted: consistent with the reported DOPs),
/// dx = (HᵀH)⁻¹Hᵀ·e, and the residuals e − H·dx are what the receiver sees (NAV-SVINFO prRes).

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/world/sky_obstructions.h"

namespace hil::gnss {

inline constexpr double kGpsL1Wavelength_m = 0.19029367;  // c / 1575.42 MHz
inline constexpr double kGpsCaChip_m = 293.05;            // c / 1.023 MHz

/// Receiver figures of the signal model; the thresholds are scenario parameters (see the README's
/// `gnss.multipath`).
struct ShadingConfig {
  std::shared_ptr<const world::SkyObstructions> obstructions;  ///< null or empty: open sky
  double track_min_dbhz = 15.0;          ///< tracking floor (below: not tracked)
  double nav_min_dbhz = 20.0;            ///< navigation floor (below: tracked, not used)
  double correlator_spacing_chip = 0.5;  ///< early–late spacing of the DLL
  bool active() const { return obstructions && !obstructions->empty(); }
};

/// What the obstructions do to one satellite's signal.
struct SignalEffect {
  double cno_change_db = 0;  ///< −inf when nothing arrives
  double code_error_m = 0, carrier_error_m = 0;
  bool nlos = false;  ///< only a reflection arrives
};

/// The effect on the signal from azimuth `az_deg`, elevation `el_deg` at antenna `p_NA_N_m`.
SignalEffect ShadeSignal(const ShadingConfig& config, const Eigen::Vector3d& p_NA_N_m,
                         double az_deg, double el_deg);

/// Position (ENU, m) and clock error the range errors of the used satellites make, with their
/// residuals (index-aligned with `sats`, 0 for the unused).
struct RangeErrorSolution {
  Eigen::Vector3d dp_N_m = Eigen::Vector3d::Zero();
  std::vector<double> residual_m;
  double sigma_m = 0;  ///< √(Σ residual² / (n − unknowns)): the receiver's own error estimate
  bool valid = false;
};
/// `range_error_m` is index-aligned with `sats`; only the used satellites count.
RangeErrorSolution SolveRangeErrors(const std::vector<SatelliteView>& sats,
                                    const std::vector<double>& range_error_m);

}  // namespace hil::gnss

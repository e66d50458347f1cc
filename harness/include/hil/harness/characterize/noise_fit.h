#pragma once
/// @file
/// Noise terms read off one axis's Allan deviation curve, the way IEEE Std 952-1997 annex C does
/// it by hand, automated:
/// - the floor: the first local minimum of the curve past any initial rise (a tone or the
///   sensor's filter at the shortest τ), where the white-noise decline ends (a
///   Gauss–Markov bias makes a bump after it and falls again beyond its correlation time, so the
///   global minimum can lie past the bump).
/// - white noise (angle / velocity random walk) N: σ(τ) = N/√τ. N = σ·√τ at the point whose
///   local log-log slope (its neighbours' secant) is nearest −1/2, searched up to the floor.
/// - bias instability B: the floor σ_floor = B·√(2 ln2 / π) ≈ 0.664 B. `resolved` only when the
///   curve has turned (the floor is not its last point, or its last slope is flatter than −1/4);
///   otherwise σ_floor/0.664 is an upper bound and said so.
/// - rate random walk K: σ(τ) = K·√(τ/3). K = σ·√(3/τ) at the point after the floor whose slope
///   is nearest +1/2, when that slope is above +0.35; otherwise not visible.
/// The same on the PSD: white noise of one-sided density S gives N = √(S/2), S the median over a
/// band (robust to tones in it; low by 1-2 % for Welch averages of 10 or more segments).

#include <optional>
#include <vector>

namespace hil::harness {

struct NoiseTerms {
  double white = 0;             ///< N, unit·√s (rad/√s, m/s/√s)
  double white_tau_s = 0;       ///< where N was read
  double white_slope = 0;       ///< the local slope there (−1/2 for a clean white region)
  double bias_instability = 0;  ///< B, unit (rad/s, m/s²)
  double bias_instability_tau_s = 0;
  bool bias_instability_resolved = false;
  std::optional<double> rate_random_walk;  ///< K, unit/√s
  double rate_random_walk_tau_s = 0;
};

/// √(2 ln2 / π): the flicker floor of the Allan deviation per unit of bias instability.
inline constexpr double kBiasInstabilityFloor = 0.66428;

/// @throws std::invalid_argument for fewer than 2 points or mismatched lengths.
NoiseTerms FitNoiseTerms(const std::vector<double>& tau_s, const std::vector<double>& adev);

/// N from a one-sided PSD: the median density over [f_lo, f_hi] (unit²/Hz) → √(median/2).
/// @throws std::invalid_argument when no bin lies in the band.
double WhiteNoiseFromPsd(const std::vector<double>& freq_hz, const std::vector<double>& density,
                         double f_lo_hz, double f_hi_hz);

}  // namespace hil::harness

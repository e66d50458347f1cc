#pragma once
/// @file
/// The GNSS velocity's noise learned from its innovations, for a receiver that does not report the
/// accuracy of its velocity (NMEA RMC/VTG: speed and course, no σ; the σ a host configures is a
/// data-sheet figure). Innovation-based adaptive estimation of the measurement noise (Mohamed and
/// Schwarz, "Adaptive Kalman filtering for INS/GPS", J. Geodesy 73, 1999, eq. 21: R̂ = Ĉ_ν − H P⁻
/// Hᵀ, Ĉ_ν the innovations' sample covariance), per horizontal axis, averaged over both axes.
///
/// Why: the fix's velocity is what carries the vehicle's motion from one fix to the next where a
/// consumer IMU cannot (a slow vehicle: its tilt random walk times g swamps the accelerations), so
/// its weight sets how long a receiver's time-correlated position error can be averaged. A data
/// sheet's velocity accuracy (u-blox 5: 0.1 m/s) is a bound over speeds and skies; the Doppler
/// velocity of a receiver at walking pace under an open sky is several times better (the emulated
/// NEO-5M: 0.03 m/s × HDOP). Weighed at the data sheet's σ the velocity adds little (estimator.md,
/// "GNSS velocity noise").
///
/// The estimate is kept at HDOP 1 (a receiver's velocity error is its Doppler ranging error times
/// the geometry's dilution, as its position error) when the fixes report an HDOP, and forgets with
/// `memory_updates`. It only ever lowers the configured σ: innovations above it say the IMU or the
/// filter is outside its model, which the GNSS velocity's innovation window handles
/// (ImuNoiseParams), not a worse receiver. Fixed size, no allocation.

namespace hil::estimator {

struct GnssVelocityNoiseParams {
  bool enabled = true;
  int min_updates = 20;        ///< updates before the estimate is used (ours: as the NIS window)
  double memory_updates = 60;  ///< exponential forgetting (ours: a minute at 1 Hz)
  double clip_sigma = 3.0;     ///< an innovation is clipped at this many σ of the configured model
  /// the configured σ's weight at the start, in updates (ours: the estimate leaves it over about a
  /// minute at 1 Hz, not at once, so a few quiet fixes do not make the filter over-trust them)
  double prior_updates = 10;
};

class GnssVelocityNoise {
 public:
  GnssVelocityNoise() = default;
  explicit GnssVelocityNoise(const GnssVelocityNoiseParams& params) : params_(params) {}

  /// One velocity update's horizontal innovations (E, N, m/s), their predicted variances
  /// (H P⁻ Hᵀ diagonal, m²/s²), the configured σ (m/s) and the fix's HDOP (0: not reported).
  void Add(double nu_e_mps, double nu_n_mps, double hph_e_mps2, double hph_n_mps2,
           double configured_std_mps, double hdop);
  /// The σ to fuse a fix of this HDOP with: the estimate (scaled to the HDOP), never above the
  /// configured σ nor below `floor_mps`; the configured σ until min_updates updates came.
  double Std(double configured_std_mps, double hdop, double floor_mps) const;
  /// The estimate at HDOP 1 (m/s); 0 before min_updates updates.
  double std_at_hdop1_mps() const;
  int updates() const { return updates_; }

 private:
  static double DopScale(double hdop);

  GnssVelocityNoiseParams params_;
  double sum_ = 0, weight_ = 0;  // forgetting sums of the unit-HDOP variance samples
  int updates_ = 0;
};

}  // namespace hil::estimator

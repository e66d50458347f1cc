#pragma once
/// @file
/// The GNSS velocity's noise learned for a receiver that does not report the accuracy of its
/// velocity (NMEA RMC/VTG: speed and course, no σ; the σ a host configures is a data-sheet figure).
/// AddIncrement() takes each fix velocity's increment against the INS's own over the same
/// interval, d = v_k − v_k−1 − Δv_INS: for white errors E[d²] = 2R, so d²/2 is a sample of R (the
/// form of innovation-based adaptive estimation, Mohamed and Schwarz, "Adaptive Kalman filtering
/// for INS/GPS", J. Geodesy 73, 1999, eq. 21, R̂ = Ĉ_ν − H P⁻ Hᵀ, with no prediction term: the
/// innovations themselves fell to the floor whenever P was pessimistic, estimator.md "GNSS velocity
/// noise"), per horizontal axis, averaged over both axes; and the increments' lag-1 products to
/// AddIncrementLag, which corrects the estimate for errors correlated from fix to fix.
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
  /// Increments (AddIncrementLag): below this estimated 1 − ρ (ρ the velocity error's correlation
  /// from one fix to the next) nothing is learned and the configured σ holds (ours: ρ > 0.8, where
  /// the lag-1 covariance is too small beside its own sampling noise to scale by)
  double min_one_minus_rho = 0.2;
};

class GnssVelocityNoise {
 public:
  GnssVelocityNoise() = default;
  explicit GnssVelocityNoise(const GnssVelocityNoiseParams& params) : params_(params) {}

  /// One fix velocity's horizontal increment against the INS's (E, N, m/s), the configured σ
  /// (m/s: the prior and the clip) and the fix's HDOP (0: not reported).
  void AddIncrement(double d_e_mps, double d_n_mps, double configured_std_mps, double hdop);
  /// Two consecutive velocity increments d_k = v_k − v_k−1 − Δv_INS and d_k−1 (E, N, m/s) of the
  /// same receiver, for its velocity error's fix-to-fix correlation ρ. Differencing hides a
  /// correlated error: for a first-order error of variance R, E[d²] = 2R(1 − ρ) and
  /// E[d_k d_k−1] = −R(1 − ρ)², so 1 − ρ = −2 E[d_k d_k−1] / E[d²]; std_at_hdop1_mps() divides the
  /// increments' variance by it (white: ρ = 0, factor 1). An INS increment error adds to E[d²]
  /// only, which raises the estimate (the safe side). A receiver whose velocity is smoothed over
  /// several fixes (an RTK rover's 10 Hz NMEA) has ρ near 1: without this the increments read it
  /// several times better than it is.
  /// `configured_std_mps`: the prior (white errors of that σ) and the clip, as in Add.
  void AddIncrementLag(double d_e_mps, double d_n_mps, double prev_d_e_mps, double prev_d_n_mps,
                       double configured_std_mps);
  /// 1 − ρ estimated from the increments (1 before any, and from the prior: white).
  double one_minus_rho() const;
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
  double lag0_ = 0, lag1_ = 0;   // forgetting sums of d² (two fixes' mean) and d_k d_k−1
  bool lag_started_ = false;
  int updates_ = 0;
};

}  // namespace hil::estimator

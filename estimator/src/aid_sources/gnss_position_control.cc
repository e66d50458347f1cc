// GNSS position aid source of the navigator's EKF: control (when and against which covariance a
// fix is fused) here, fusion in ErrorStateEkf::UpdatePosition. See estimator.md, "Consistency
// and robustness".
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

const char* AidSourceName(int source) {
  switch (source) {
    case kAidGnssPosition:
      return "gnss_pos";
    case kAidGnssVelocity:
      return "gnss_vel";
    case kAidNonHolonomic:
      return "nhc";
    case kAidZeroVelocity:
      return "zupt";
    case kAidZeroAngularRate:
      return "zaru";
    default:
      return "?";
  }
}

void Navigator::Record(int source, const UpdateResult& r) {
  if (r.dof <= 0) return;
  InnovationMonitor& m = monitors_[source];
  m.Record(r.nis, r.dof, r.accepted, r.excess, params_.robust.nis_clip_per_dof);
  NavigatorStats::Aid& a = stats_.aid[source];
  a.accepted = m.accepted();
  a.rejected = m.rejected();
  a.windows_above = m.windows_above();
  a.windows_below = m.windows_below();
  a.last_nis = m.last_nis();
  a.window_nis_per_dof = m.window_mean_nis_per_dof();
  a.window_count = m.window_count();
  const ChiSquareBand band = m.window_band();
  a.band_low = band.low;
  a.band_high = band.high;
  if (source == kAidGnssVelocity) AdaptAccelNoise();
  if (source == kAidNonHolonomic) AdaptNhcNoise();
}

bool Navigator::CheckGnssStep(const GnssSample& g, const Eigen::Vector3d& p) {
  const Eigen::Vector3d vel_var = ekf_.covariance().diagonal().segment<3>(ekf_index::kVel);
  const bool step = step_.IsStep(g.t, p, g.pos_std_enu_m, ekf_.AntennaPosition(), vel_var);
  if (step) ++stats_.gnss_steps;
  return step;
}

double Navigator::PositionGateScale() const {
  const RobustnessParams& rp = params_.robust;
  const InnovationMonitor& m = monitors_[kAidGnssPosition];
  if (!rp.gate_follows_median_nis || m.window_count() < rp.gate_median_min_count) return 1.0;
  constexpr double kChi2Dof3MedianPerDof = 2.365974 / 3.0;  // χ²(3)'s median over 3
  return std::max(1.0, m.window_median_nis_per_dof() / kChi2Dof3MedianPerDof);
}

bool Navigator::InGapRecovery(GpsTime t, bool time_gap) {
  const Nanoseconds max = params_.robust.gap_recovery_max;
  if (time_gap && max > Nanoseconds{0}) {
    recovery_until_ = t + max;
    recovery_passes_ = 0;
    ++stats_.gap_recoveries;
  }
  if (recovery_until_ && t > *recovery_until_) recovery_until_.reset();
  return recovery_until_.has_value();
}

UpdateResult Navigator::ControlGnssPosition(const GnssSample& g, const Eigen::Vector3d& p) {
  const RobustnessParams& rp = params_.robust;
  // a fix after a gap meets a covariance the configured noise may have grown too little
  const bool time_gap = last_fix_seen_t_ && g.t - *last_fix_seen_t_ > rp.gap_after;
  bool after_gap = time_gap;
  last_fix_seen_t_ = g.t;
  const bool fades = rp.FadesToFixes();
  const bool step = fades && CheckGnssStep(g, p);
  // an RTK fix episode's first fix is judged before it can move the filter (RtkFixFrames)
  if (const std::optional<UpdateResult> suspect = ControlRtkFix(g, p)) return *suspect;
  const bool recovering = fades && InGapRecovery(g.t, time_gap);
  const double gate_scale = PositionGateScale();
  // the gap's first fix: gated, and faded to if the gap outgrew the covariance (below)
  const bool ungated = recovering && !time_gap;
  ekf_.SetGateScale(ungated ? std::numeric_limits<double>::infinity() : gate_scale);
  UpdateResult r = ekf_.UpdatePosition(p, g.pos_std_enu_m);
  ekf_.SetGateScale(1.0);
  if (ungated && r.accepted) {
    ++stats_.recovery_fixes;
    // back at its fixes: gap_recovery_passes fixes in a row after the gap's first that the gate
    // would have taken
    recovery_passes_ = ekf_.WithinGate(r.nis, r.dof, gate_scale) ? recovery_passes_ + 1 : 0;
    if (recovery_passes_ >= rp.gap_recovery_passes) recovery_until_.reset();
  }
  if (fades && r.dof > 0) {
    // the GNSS consistency check: a rejected step is the receiver's, not the model's
    if (glitch_since_ && (r.accepted || !InGnssGlitch(g.t))) {
      glitch_since_.reset();  // over, or lasting long enough to be believed
    } else if (glitch_since_ && step) {
      glitch_since_.reset();  // the fixes stepped back: fade to them as after a gap
      after_gap = true;
    } else if (!r.accepted && step && std::isfinite(r.nis)) {
      glitch_since_ = g.t;
      ++stats_.gnss_glitches;
    }
    if (InGnssGlitch(g.t)) {
      ++stats_.gnss_glitch_rejected;
      step_.Remember(g.t, p, g.pos_std_enu_m, ekf_.AntennaPosition());
      return r;
    }
  }
  if (!r.accepted && r.dof > 0 && fades && std::isfinite(r.nis)) {
    const bool persistent =
        monitors_[kAidGnssPosition].consecutive_rejected() + 1 >= rp.reject_fade_count &&
        first_rejected_t_ && g.t - *first_rejected_t_ >= rp.reject_fade_after;
    // fading memory to this fix: P ← λ P with λ the factor that makes its innovation consistent
    const double lambda = std::min(r.excess, rp.max_fading_factor);
    if ((after_gap || persistent) && lambda > 1.0) {
      // after a gap in time what the filter knew at its start stays known: only the gap's white
      // noise is scaled to the fix (a glitch's step back keeps the whole covariance's fading)
      if (!(time_gap && rp.fade_gap_noise &&
            ekf_.FadeGapNoiseTo(p, g.pos_std_enu_m, rp.max_fading_factor)))
        ekf_.InflateCovariance(lambda);
      ++stats_.fadings;
      ++(after_gap ? stats_.gap_fadings : stats_.reject_fadings);
      const UpdateResult retry = ekf_.UpdatePosition(p, g.pos_std_enu_m);
      r.accepted = retry.accepted;
    }
  }
  step_.Remember(g.t, p, g.pos_std_enu_m, ekf_.AntennaPosition());
  Record(kAidGnssPosition, r);
  // the IMU found outside its model by the velocity (AdaptAccelNoise): the position window sizes
  // its noise as well
  if (rp.adaptive || stats_.accel_noise_raises > 0) AdaptToInnovations();
  return r;
}

void Navigator::AdaptToInnovations() {
  // innovation-based adaptation of the process noise (Mohamed and Schwarz 1999): a window whose
  // mean NIS lies above its χ² band scales the IMU noise by the window's mean NIS per degree of
  // freedom (the covariance is faded only for a fix after a gap or a run of rejections: fading
  // it for a window, too, cost seed004 0.015 -> 0.136 m RMSE);
  // a window whose mean is below 1 scales that noise back down (never below the configured
  // noise).
  InnovationMonitor& m = monitors_[kAidGnssPosition];
  if (!m.window_full()) return;
  const RobustnessParams& rp = params_.robust;
  const double mean = m.window_mean_nis_per_dof();
  double q = ekf_.process_noise_scale();
  // persistently above: the mean above the band and most updates above their expectation (a
  // few outliers in a window of a pessimistic filter are not a wrong model)
  if (m.window_above_band() && m.window_median_nis_per_dof() > 1.0) {
    q = std::min(q * std::min(mean, rp.max_scale_step), rp.max_process_noise_scale);
    m.ClearWindow();
  } else if (mean < 1.0 && q > 1.0) {
    // the scaled noise overstates the errors now: back towards the configured noise
    q = std::max(1.0, q * std::max(mean, 1.0 / rp.max_scale_step));
    m.ClearWindow();
  }
  ekf_.SetProcessNoiseScale(q);
  stats_.process_noise_scale = q;
}

}  // namespace hil::estimator

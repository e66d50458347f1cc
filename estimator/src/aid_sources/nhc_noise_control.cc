// The non-holonomic constraint's noise against its own innovations (NhcNoiseParams in
// navigator.h; estimator.md, "When the NHC's premise fails").
#include <algorithm>

#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::AdaptNhcNoise() {
  const NhcNoiseParams& p = params_.nhc_noise;
  InnovationMonitor& m = monitors_[kAidNonHolonomic];
  if (!p.enabled || params_.mode != NavMode::kEkf || !m.window_full()) return;
  // without fixes the constraint's misses are not told from the INS's drift: the scale is held
  if (filter_t_ - last_gnss_fused_t_ > params_.robust.gap_after) {
    nhc_far_updates_ = 0;
    return;
  }
  const double mean = m.window_mean_nis_per_dof();
  const double median = m.window_median_nis_per_dof();
  double scale = ekf_.nhc_noise_scale();
  // first raise: far above the band for persist_updates in a row (a vehicle the constraint holds
  // for gets there for a moment at most); once raised, the scale follows the window's band
  const bool far = mean > p.raise_nis_per_dof && median > p.raise_nis_per_dof;
  nhc_far_updates_ = far ? nhc_far_updates_ + 1 : 0;
  const bool persistent = nhc_far_updates_ >= p.persist_updates;
  const bool above = scale > 1.0 && m.window_above_band() && median > 1.0;
  if (persistent || above) {
    nhc_far_updates_ = 0;
    scale = std::min(scale * std::min(mean, p.max_step), p.max_scale);
    ++stats_.nhc_noise_raises;
    m.ClearWindow();
  } else if (scale > 1.0 && m.window_below_band()) {
    // back down slowly: a vehicle that pauses or goes straight for a moment has not come back
    // into the constraint, and a scale too small going into an outage costs more than one too large
    scale = std::max(1.0, scale * std::max(mean, 1.0 / p.max_lower_step));
    m.ClearWindow();
  }
  ekf_.SetNhcNoiseScale(scale);
  stats_.nhc_noise_scale = scale;
}

}  // namespace hil::estimator

// RTK fix episodes, and the suspect one's hold (rtk_fix_check.h).
#include "hil/estimator/rtk_fix_check.h"

namespace hil::estimator {

bool RtkFixCheck::BeginsEpisode(GpsTime t, int quality) {
  if (!params_.enabled) return false;
  const bool fixed = quality == params_.fixed_quality;
  const bool gap = prev_t_ && t - *prev_t_ > params_.trusted_within;
  const bool begins = fixed && (prev_quality_ != params_.fixed_quality || gap);
  prev_quality_ = quality;
  prev_t_ = t;
  if (!fixed || begins) suspect_since_.reset();
  return begins;
}

void RtkFixCheck::BeginSuspect(GpsTime t) {
  suspect_since_ = t;
  ++suspect_episodes_;
  ++suspect_fixes_;
}

}  // namespace hil::estimator

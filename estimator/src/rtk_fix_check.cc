// A new RTK fixed solution that the INS contradicts from its first fix (rtk_fix_check.h).
#include "hil/estimator/rtk_fix_check.h"

namespace hil::estimator {

bool RtkFixCheck::Observe(GpsTime t, int quality, bool accepted,
                          std::optional<GpsTime> last_accepted_t) {
  if (!params_.enabled) return false;
  const bool fixed = quality == params_.fixed_quality;
  const bool gap = prev_t_ && t - *prev_t_ > params_.trusted_within;
  const bool new_episode = fixed && (prev_quality_ != params_.fixed_quality || gap);
  prev_quality_ = quality;
  prev_t_ = t;
  if (new_episode) {
    decided_ = false;
    suspect_since_.reset();
  }
  if (!fixed || accepted) {
    // float or no RTK: not an integer fix; accepted: the filter agrees with the episode
    decided_ = decided_ || fixed;
    suspect_since_.reset();
    return false;
  }
  if (suspect_since_) {
    if (t - *suspect_since_ < params_.hold) {
      ++suspect_fixes_;
      return true;
    }
    suspect_since_.reset();  // held long enough to be believed
    return false;
  }
  if (decided_) return false;
  decided_ = true;
  // the episode's first fix contradicts a filter that was aided until just before
  if (!last_accepted_t || t - *last_accepted_t > params_.trusted_within) return false;
  suspect_since_ = t;
  ++suspect_episodes_;
  ++suspect_fixes_;
  return true;
}

}  // namespace hil::estimator

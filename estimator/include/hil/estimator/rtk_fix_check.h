#pragma once
/// @file
/// @system
/// name: RtkFixCheck (RTK fix episodes, and the suspect one's hold)
/// input: every fix's time and GGA quality before its update; the navigator's verdict on an
///        episode's first fix (RtkFixFrames)
/// output: whether a fix begins a fix episode, whether the current episode is suspect
/// @endsystem
///
/// An RTK rover that (re)fixes its ambiguities after a float period sometimes picks a wrong
/// integer combination: it reports quality 4 (fixed) with centimetre σ while its position is a
/// whole-cycle combination (decimetres) off, and holds it until a later check throws it out. A fix
/// episode is a run of quality-4 fixes after anything else (or after `trusted_within` without
/// fixes). The navigator judges each episode's first fix (RtkFixFrames): one that lies in another
/// frame than the filter's makes the episode suspect, and its fixes are fused less that frame's
/// offset (a wrong integer fix is a constant offset while it is held) until the quality changes
/// or the episode has been suspect for `hold` (then the navigator adopts it). No allocation.
#include <cstdint>
#include <optional>

#include "hil/estimator/time_types.h"

namespace hil::estimator {

/// Parameters (chosen here; no source gives them).
struct RtkFixCheckParams {
  bool enabled = true;
  int fixed_quality = 4;  ///< GGA quality of an RTK fixed solution
  /// the filter counts as aided when it accepted a fix (float ones included) this recently before
  /// the episode's first fix: 1.5 s, the navigator's gap_after
  Nanoseconds trusted_within{1'500'000'000};
  /// longest suspect episode: 60 s, longer than the tens of seconds a rover takes to throw out a
  /// wrong fix (our choice), short enough that a filter does not hold a receiver that really
  /// moved (a new base) at arm's length for minutes
  Nanoseconds hold{60'000'000'000};
  /// an episode's first fix lies in a frame (the filter's, or an earlier episode's) when the NIS
  /// of its offset from that frame (3 degrees of freedom) is at most this: χ²₃'s 0.999 quantile,
  /// so that one right fix behind a consistent right filter in a thousand is taken for another
  /// frame (RtkFixFrames)
  double same_frame_nis = 16.27;
};

class RtkFixCheck {
 public:
  RtkFixCheck() = default;
  explicit RtkFixCheck(const RtkFixCheckParams& params) : params_(params) {}

  /// Each fix before its update: true when it begins a fix episode. A fix that is not fixed
  /// (float, no RTK) or begins a new episode ends a suspect one.
  bool BeginsEpisode(GpsTime t, int quality);
  /// The filter was aided (accepted a fix) within trusted_within before t.
  bool FilterAided(GpsTime t, std::optional<GpsTime> last_accepted_t) const {
    return last_accepted_t && t - *last_accepted_t <= params_.trusted_within;
  }
  /// The episode begun at t is suspect (its first fix lies in another frame than the filter's).
  void BeginSuspect(GpsTime t);
  /// A fix of the suspect episode, fused less its offset.
  void CountSuspectFix() { ++suspect_fixes_; }
  /// The suspect episode has been held for `hold` at t: it is believed.
  bool HoldOver(GpsTime t) const { return suspect_since_ && t - *suspect_since_ >= params_.hold; }
  void EndSuspicion() { suspect_since_.reset(); }
  bool suspect() const { return suspect_since_.has_value(); }
  std::uint64_t suspect_episodes() const { return suspect_episodes_; }
  std::uint64_t suspect_fixes() const { return suspect_fixes_; }
  const RtkFixCheckParams& params() const { return params_; }

 private:
  RtkFixCheckParams params_;
  int prev_quality_ = 0;
  std::optional<GpsTime> prev_t_, suspect_since_;
  std::uint64_t suspect_episodes_ = 0, suspect_fixes_ = 0;
};

}  // namespace hil::estimator

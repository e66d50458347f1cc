#pragma once
/// @file
/// @system
/// name: RtkFixCheck (a new RTK fixed solution that the INS contradicts from its first fix)
/// input: every fix's time and GGA quality, whether the filter's gate accepted it, the time of the
///        filter's last accepted fix
/// output: whether the fix belongs to a suspect fix episode (a probable wrong integer fix)
/// @endsystem
///
/// An RTK rover that (re)fixes its ambiguities after a float period sometimes picks a wrong
/// integer combination: it reports quality 4 (fixed) with centimetre σ while its position is a
/// whole-cycle combination (decimetres) off, and holds it until a later check throws it out. A
/// right fix agrees with a filter that was aided until just before; a wrong one contradicts it by
/// the same offset at every fix. A fix episode (quality 4 after anything else) whose first fix the
/// gate rejects while the filter was aided within `trusted_within` is suspect: its fixes are
/// rejected without being evidence against the filter (no reset clock, no fading) until one passes
/// the gate, the quality changes, or the episode has been suspect for `hold` (then its fixes are
/// ordinary rejected fixes: a receiver that keeps a fix that long is believed, the filter's reset
/// being the last resort). While an episode is suspect the navigator fuses its fixes less the
/// offset its first fix showed (a wrong integer fix is a constant offset while it is held), and
/// their velocities. A filter that coasted (no fix accepted within `trusted_within`) is not
/// trusted over a new fix. No allocation.
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
  /// wrong fix (our choice), short enough that a filter does not coast for minutes on GNSS
  /// velocity alone
  Nanoseconds hold{60'000'000'000};
};

class RtkFixCheck {
 public:
  RtkFixCheck() = default;
  explicit RtkFixCheck(const RtkFixCheckParams& params) : params_(params) {}

  /// One fix after its gate decision. True when it belongs to a suspect episode (it is rejected,
  /// and no evidence against the filter).
  bool Observe(GpsTime t, int quality, bool accepted, std::optional<GpsTime> last_accepted_t);
  /// The current episode is suspect.
  bool suspect() const { return suspect_since_.has_value(); }
  /// The fix last observed began a suspect episode.
  bool suspect_began() const { return suspect_since_ && prev_t_ && *suspect_since_ == *prev_t_; }
  std::uint64_t suspect_episodes() const { return suspect_episodes_; }
  std::uint64_t suspect_fixes() const { return suspect_fixes_; }

 private:
  RtkFixCheckParams params_;
  int prev_quality_ = 0;
  bool decided_ = false;  // the current episode's first fix was judged (accepted or suspect)
  std::optional<GpsTime> prev_t_, suspect_since_;
  std::uint64_t suspect_episodes_ = 0, suspect_fixes_ = 0;
};

}  // namespace hil::estimator

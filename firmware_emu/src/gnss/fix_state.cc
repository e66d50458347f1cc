#include "hil/firmware_emu/gnss/fix_state.h"

namespace hil::gnss {

void FixState::Restart(Time t, StartKind kind) {
  kind_ = kind;
  t_start_ = t;
  const double ttff = kind == StartKind::kCold   ? config_.ttff_cold_s
                      : kind == StartKind::kWarm ? config_.ttff_warm_s
                                                 : config_.ttff_hot_s;
  t_fix_allowed_ = t + DurationFromSeconds(ttff);
  had_fix_ = false;
  lost_ = false;
  orbit_known_ = kind != StartKind::kCold;
  ttff_ms_ = 0;
}

FixStatus FixState::Step(Time t, int usable_sv, FixMode mode) {
  FixStatus st;
  st.msss_ms =
      static_cast<std::uint32_t>(ToNs(t) > ToNs(t_start_) ? (t - t_start_).count() / 1000000 : 0);
  st.time_known = kind_ != StartKind::kCold || had_fix_ ||
                  t - t_start_ >= DurationFromSeconds(config_.cold_time_known_s);
  const int min_sv = mode == FixMode::k3DOnly ? 4 : 3;
  if (usable_sv < min_sv) {
    if (!lost_) t_lost_ = t;
    lost_ = true;
  } else if (lost_) {
    lost_ = false;
    if (had_fix_) {
      const double outage_s = ToSeconds(t - t_lost_);
      const double wait =
          outage_s > config_.long_outage_s ? config_.ttff_warm_s : config_.reacquisition_s;
      const Time t_back = t + DurationFromSeconds(wait);
      if (t_back > t_fix_allowed_) t_fix_allowed_ = t_back;
    }
  }
  if (!lost_ && t >= t_fix_allowed_) {
    if (!had_fix_) {
      had_fix_ = true;
      ttff_ms_ = static_cast<std::uint32_t>((t - t_start_).count() / 1000000);
    }
    orbit_known_ = true;
    if (mode == FixMode::k2DOnly)
      st.fix_type = FixType::k2D;
    else
      st.fix_type = usable_sv >= 4 ? FixType::k3D : FixType::k2D;
  }
  st.orbit_known = orbit_known_;
  st.ttff_ms = ttff_ms_;
  return st;
}

}  // namespace hil::gnss

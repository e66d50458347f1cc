#pragma once
/// @file
/// @system
/// name: FixState (acquisition and fix state machine of a standalone receiver)
/// input: at each navigation epoch, the number of satellites usable for navigation
/// output: fix type (none/2D/3D), time-known and orbit-known flags, TTFF and msss
/// rate: the navigation rate
/// @endsystem
///
/// After a (re)start the receiver acquires for its time to first fix, which depends on the start
/// kind: cold (no almanac, ephemeris, time or position: ≈ 29 s; satellites are tracked but their
/// elevation/azimuth are unknown until the fix), warm (almanac and time known, no ephemeris:
/// ≈ 28 s), hot (everything valid: ≈ 1 s). Figures from a u-blox-5/6-class data sheet
/// (shared/reference/ublox5.md §6, UNVERIFIED for the NEO-5M) and configurable.
/// With fewer than 3 usable satellites the fix is lost; when satellites come back, the fix
/// returns after the re-acquisition time (short outages) or a warm-start TTFF (outages longer
/// than `long_outage_s`, when the ephemerides have aged). 3 satellites give a 2D fix, 4 or more
/// a 3D fix, unless the fix mode (CFG-NAV5) forbids it.

#include <cstdint>

#include "hil/firmware_emu/gnss/gnss_fix.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::gnss {

enum class StartKind { kCold, kWarm, kHot };

struct FixStateConfig {
  double ttff_cold_s = 29.0, ttff_warm_s = 28.0, ttff_hot_s = 1.0;
  double reacquisition_s = 1.0;    ///< time to regain the fix after a short outage
  double long_outage_s = 1800.0;   ///< outages longer than this need a warm-start TTFF
  double cold_time_known_s = 8.0;  ///< cold start: UTC time is decoded this long after start
};

/// CFG-NAV5 fixMode.
enum class FixMode : std::uint8_t { k2DOnly = 1, k3DOnly = 2, kAuto = 3 };

struct FixStatus {
  FixType fix_type = FixType::kNoFix;
  bool time_known = false;    ///< UTC/GPS time valid (NMEA time fields are printed)
  bool orbit_known = false;   ///< elevation/azimuth of satellites known
  std::uint32_t ttff_ms = 0;  ///< time to first fix of the current start (0 before it)
  std::uint32_t msss_ms = 0;  ///< milliseconds since (re)start
};

class FixState {
 public:
  explicit FixState(const FixStateConfig& config) : config_(config) {}
  /// (Re)starts the receiver at `t`.
  void Restart(Time t, StartKind kind);
  /// Advances to epoch `t` with `usable_sv` satellites usable for navigation.
  FixStatus Step(Time t, int usable_sv, FixMode mode = FixMode::kAuto);
  StartKind start_kind() const { return kind_; }

 private:
  FixStateConfig config_;
  StartKind kind_ = StartKind::kHot;
  Time t_start_{};
  Time t_fix_allowed_{};  // acquisition ends here
  Time t_lost_{};         // when the sky went away
  bool had_fix_ = false;  // a fix since the start
  bool lost_ = false;     // currently without enough satellites
  bool orbit_known_ = false;
  std::uint32_t ttff_ms_ = 0;
};

}  // namespace hil::gnss

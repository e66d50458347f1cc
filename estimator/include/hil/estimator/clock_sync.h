#pragma once
/// @file
/// Maps the MCU's free-running u32 tick (nominal 1 MHz, crystal offset and drift unknown) onto GPS
/// time through the latched time pulse: each TIME_PULSE gives (tick at the edge, whole GPS second).
/// The tick is unwrapped to 64 bits; the tick rate is estimated from consecutive pulses (smoothed),
/// and t_gps(tick) = t_gps(last pulse) + (tick − tick_pulse) / rate. Host arrival times are not
/// used.

#include <cstdint>
#include <optional>

#include "hil/estimator/time_types.h"

namespace hil::estimator {

class ClockSync {
 public:
  explicit ClockSync(double nominal_tick_hz = 1e6)
      : rate_hz_(nominal_tick_hz), nominal_hz_(nominal_tick_hz) {}
  /// Unwraps a 32-bit tick against the previous one (ticks must be presented in stream order).
  std::int64_t Unwrap(std::uint32_t tick);
  /// A time pulse: the unwrapped tick latched at the edge and the GPS time of the edge.
  void AddPulse(std::int64_t tick, GpsTime t_gps);
  /// GPS time of an unwrapped tick; nullopt before the first pulse.
  std::optional<GpsTime> ToGps(std::int64_t tick) const;
  /// Estimated tick rate (Hz) and its offset from nominal (ppm).
  double rate_hz() const { return rate_hz_; }
  double offset_ppm() const { return (rate_hz_ / nominal_hz_ - 1.0) * 1e6; }
  /// Restart after an MCU reset (tick back to 0).
  void Reset();
  std::uint64_t pulses() const { return pulses_; }

 private:
  double rate_hz_, nominal_hz_;
  bool have_tick_ = false;
  std::uint32_t last_raw_ = 0;
  std::int64_t wraps_ = 0;
  bool have_pulse_ = false;
  std::int64_t pulse_tick_ = 0;
  GpsTime pulse_t_{};
  std::uint64_t pulses_ = 0;
};

}  // namespace hil::estimator

#include "hil/estimator/clock_sync.h"

#include <cmath>

namespace hil::estimator {

std::int64_t ClockSync::Unwrap(std::uint32_t tick) {
  if (have_tick_ && tick < last_raw_ && last_raw_ - tick > 0x80000000u) ++wraps_;
  have_tick_ = true;
  last_raw_ = tick;
  return wraps_ * (std::int64_t{1} << 32) + tick;
}

void ClockSync::AddPulse(std::int64_t tick, GpsTime t_gps) {
  if (have_pulse_ && t_gps > pulse_t_ && tick > pulse_tick_) {
    const double measured = static_cast<double>(tick - pulse_tick_) /
                            (static_cast<double>((t_gps - pulse_t_).count()) * 1e-9);
    // reject implausible rates (missed pulses are fine: the interval is measured in GPS time)
    if (std::abs(measured / nominal_hz_ - 1.0) < 1e-3) {
      const double w = pulses_ < 3 ? 1.0 : 0.2;
      rate_hz_ = (1.0 - w) * rate_hz_ + w * measured;
    }
  }
  have_pulse_ = true;
  pulse_tick_ = tick;
  pulse_t_ = t_gps;
  ++pulses_;
}

std::optional<GpsTime> ClockSync::ToGps(std::int64_t tick) const {
  if (!have_pulse_) return std::nullopt;
  return pulse_t_ +
         Nanoseconds{std::llround(static_cast<double>(tick - pulse_tick_) / rate_hz_ * 1e9)};
}

void ClockSync::Reset() {
  have_tick_ = false;
  wraps_ = 0;
  have_pulse_ = false;
}

}  // namespace hil::estimator

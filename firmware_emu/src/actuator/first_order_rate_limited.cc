#include "hil/firmware_emu/actuator/first_order_rate_limited.h"

#include <algorithm>
#include <cmath>

namespace hil::actuator {
namespace {

// A ramp at `rate` from x towards target for at most dt (it stops at the target).
LagStep Ramp(double x, double target, double rate, double dt) {
  const double e = target - x;
  const double sign = e >= 0 ? 1.0 : -1.0;
  const double reach_s = std::fabs(e) / rate;
  const double t_ramp = std::min(dt, reach_s);
  LagStep s;
  s.x = t_ramp < reach_s ? x + sign * rate * t_ramp : target;
  s.integral = x * t_ramp + 0.5 * sign * rate * t_ramp * t_ramp + target * (dt - t_ramp);
  return s;
}

}  // namespace

LagStep AdvanceFirstOrderRateLimited(double x, double target, double tau_s, double rate_per_s,
                                     double dt_s) {
  if (dt_s <= 0) return {x, 0.0};
  if (tau_s <= 0) {
    if (rate_per_s <= 0) return {target, target * dt_s};
    return Ramp(x, target, rate_per_s, dt_s);
  }
  LagStep out;
  double remaining_s = dt_s;
  double start = x;
  const double e = target - x;
  if (rate_per_s > 0 && std::fabs(e) > rate_per_s * tau_s) {
    const double sign = e >= 0 ? 1.0 : -1.0;
    const double ramp_s = (std::fabs(e) - rate_per_s * tau_s) / rate_per_s;
    if (remaining_s <= ramp_s) return Ramp(x, target, rate_per_s, remaining_s);
    out.integral = x * ramp_s + 0.5 * sign * rate_per_s * ramp_s * ramp_s;
    remaining_s -= ramp_s;
    start = target - sign * rate_per_s * tau_s;
  }
  const double err = target - start;
  const double decay = std::exp(-remaining_s / tau_s);
  out.x = target - err * decay;
  out.integral += target * remaining_s - err * tau_s * (1.0 - decay);
  return out;
}

}  // namespace hil::actuator

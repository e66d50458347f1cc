#pragma once
/// @file
/// The motion law every emulated actuator shares: a first-order lag towards a target whose slope is
/// capped, x' = clamp((target − x) / τ, −r, +r), advanced in closed form (a ramp at the rate limit
/// until the remaining error is r·τ, then an exponential), so the result does not depend on how
/// the caller splits time. The integral of x over the step comes with it (a wheel's angle from its
/// speed).

namespace hil::actuator {

struct LagStep {
  double x = 0;         ///< state at the end of the step
  double integral = 0;  ///< ∫ x dt over the step
};

/// Advances `dt_s` seconds from `x` with a constant target; τ ≤ 0 means no lag (pure rate limit),
/// rate ≤ 0 means no rate limit (both ≤ 0: x jumps to the target).
LagStep AdvanceFirstOrderRateLimited(double x, double target, double tau_s, double rate_per_s,
                                     double dt_s);

}  // namespace hil::actuator

#pragma once
/// @file
/// The truth's actuator lags (vehicle.h) in closed form, for a command held constant from t₀ on
/// (integrated by CVODE's Adams method, a short lag's eigenvalue −1/τ would limit every step to
/// about τ), and the closed loop's first-order hold of an emulated actuator's sampled output.

namespace hil::truth {

/// First-order lag ẋ = (c − x)/τ from x(t₀) = x0, at t₀ + s (s ≥ 0, τ > 0):
/// x = c + (x0 − c)·e^(−s/τ). Exactly x0 when x0 = c.
double FirstOrderLagAt(double x0, double c, double tau_s, double s);

/// The steering lag with a smooth rate limit, ẋ = r·tanh((c − x)/(τ r)), from x(t₀) = x0, at
/// t₀ + s (s ≥ 0, τ > 0, r > 0). With a = τ r and z = (c − x)/a the equation is ż = −tanh(z)/τ,
/// whose solution is sinh z = sinh z₀ · e^(−s/τ); for large |z| (the rate limit) it is
/// z = z₀ − s/τ, computed in logarithms so that nothing overflows.
double RateLimitedLagAt(double x0, double c, double tau_s, double rate_per_s, double s);

/// First-order hold: a ramp from x(t₀) = x0 that reaches c at t₀ + hold and stays there, at
/// t₀ + s (s ≥ 0, hold > 0). Exactly c from s ≥ hold on.
double LinearHoldAt(double x0, double c, double hold_s, double s);

}  // namespace hil::truth

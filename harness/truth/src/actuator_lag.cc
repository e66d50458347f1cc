#include "hil/truth/actuator_lag.h"

#include <cmath>
#include <numbers>

namespace hil::truth {

double FirstOrderLagAt(double x0, double c, double tau_s, double s) {
  if (x0 == c) return c;
  return c + (x0 - c) * std::exp(-s / tau_s);
}

double RateLimitedLagAt(double x0, double c, double tau_s, double rate_per_s, double s) {
  if (x0 == c) return c;
  const double a = tau_s * rate_per_s;
  const double z0 = (c - x0) / a;
  const double k = s / tau_s;
  const double abs_z0 = std::fabs(z0);
  double abs_z = 0;
  if (abs_z0 < 20) {
    abs_z = std::asinh(std::sinh(abs_z0) * std::exp(-k));
  } else {
    // log(sinh|z₀|) − s/τ, then asinh(e^L) = L + log(1 + √(1 + e^(−2L))) for L ≥ 0
    const double log_sinh = abs_z0 - std::numbers::ln2 + std::log(-std::expm1(-2 * abs_z0));
    const double l = log_sinh - k;
    abs_z = l >= 0 ? l + std::log(1 + std::sqrt(1 + std::exp(-2 * l))) : std::asinh(std::exp(l));
  }
  return c - std::copysign(abs_z * a, z0);
}

double LinearHoldAt(double x0, double c, double hold_s, double s) {
  if (s >= hold_s || x0 == c) return c;
  return x0 + (c - x0) * (s / hold_s);
}

}  // namespace hil::truth

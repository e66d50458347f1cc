// The closed-form actuator lags against the differential equations they solve, integrated
// independently (RK4, 1 µs steps), and their limits.
#include "hil/truth/actuator_lag.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace hil::truth {
namespace {

double Rk4(double x, double s, double (*f)(double, double, double, double), double c, double tau,
           double r) {
  const int n = static_cast<int>(std::lround(s / 1e-6));
  const double h = s / n;
  for (int i = 0; i < n; ++i) {
    const double k1 = f(x, c, tau, r), k2 = f(x + h / 2 * k1, c, tau, r);
    const double k3 = f(x + h / 2 * k2, c, tau, r), k4 = f(x + h * k3, c, tau, r);
    x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return x;
}
double LinearRate(double x, double c, double tau, double /*r*/) { return (c - x) / tau; }
double TanhRate(double x, double c, double tau, double r) {
  return r * std::tanh((c - x) / (tau * r));
}

TEST(ActuatorLagTest, FirstOrderLagMatchesItsEquation) {
  for (const double s : {0.0, 2e-4, 1e-3, 5e-3, 0.01}) {
    EXPECT_NEAR(FirstOrderLagAt(0.4, 0.5, 1e-3, s), Rk4(0.4, s, LinearRate, 0.5, 1e-3, 0), 1e-13);
  }
  EXPECT_EQ(FirstOrderLagAt(0.5, 0.5, 1e-3, 0.01), 0.5);  // held exactly at the command
}

TEST(ActuatorLagTest, LinearHoldRampsToTheCommandOverTheHold) {
  EXPECT_EQ(LinearHoldAt(0.4, 0.5, 0.01, 0.0), 0.4);
  EXPECT_NEAR(LinearHoldAt(0.4, 0.5, 0.01, 0.0025), 0.425, 1e-15);
  EXPECT_EQ(LinearHoldAt(0.4, 0.5, 0.01, 0.01), 0.5);  // reached, and held exactly
  EXPECT_EQ(LinearHoldAt(0.4, 0.5, 0.01, 1.0), 0.5);
  EXPECT_EQ(LinearHoldAt(0.5, 0.5, 0.01, 0.004), 0.5);
}

TEST(ActuatorLagTest, RateLimitedLagMatchesItsEquationFromLinearToSaturated) {
  // GIVEN a steering lag of 1 ms with a rate limit of 1000 deg/s (a = τ r = 0.0175 rad), and
  // steps from 1e-4 rad (linear) to 0.6 rad (|z₀| = 34: the rate limit for 33 ms)
  const double tau = 1e-3, r = 1000 * std::numbers::pi / 180;
  for (const double step : {1e-4, 0.01, 0.1, 0.6, -0.6}) {
    for (const double s : {1e-4, 1e-3, 0.01, 0.03, 0.05}) {
      // THEN it agrees with the integrated equation
      EXPECT_NEAR(RateLimitedLagAt(0.1, 0.1 + step, tau, r, s),
                  Rk4(0.1, s, TanhRate, 0.1 + step, tau, r), 1e-12)
          << "step " << step << " s " << s;
    }
  }
  // AND a saturated lag moves at the rate limit, and nothing overflows for |z₀| of 10⁴
  EXPECT_NEAR(RateLimitedLagAt(0, 0.6, tau, r, 0.01), r * 0.01, 1e-12);
  EXPECT_NEAR(RateLimitedLagAt(0, 200, tau, r, 1.0), r * 1.0, 1e-9);
  EXPECT_EQ(RateLimitedLagAt(0.2, 0.2, tau, r, 1.0), 0.2);
}

}  // namespace
}  // namespace hil::truth

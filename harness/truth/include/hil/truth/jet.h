#pragma once
/// @file
/// A second-order Taylor jet in time: a value with its first and second time derivatives,
/// propagated exactly through arithmetic and the few functions the body kinematics needs.
/// It lets the truth compute attitude, angular rate and angular acceleration (and position,
/// velocity and acceleration) from one closed-form expression, so that they are exact
/// derivatives of each other rather than separately modelled quantities.

#include <cmath>

namespace hil::truth {

/// x(t), ẋ(t), ẍ(t) at one instant.
struct Jet2 {
  double v = 0;   ///< value
  double d = 0;   ///< first time derivative
  double dd = 0;  ///< second time derivative

  constexpr Jet2() = default;
  constexpr Jet2(double value) : v(value) {}  // NOLINT: a constant is a jet with zero derivatives
  constexpr Jet2(double value, double d1, double d2) : v(value), d(d1), dd(d2) {}
};

constexpr Jet2 operator+(Jet2 a, Jet2 b) { return {a.v + b.v, a.d + b.d, a.dd + b.dd}; }
constexpr Jet2 operator-(Jet2 a, Jet2 b) { return {a.v - b.v, a.d - b.d, a.dd - b.dd}; }
constexpr Jet2 operator-(Jet2 a) { return {-a.v, -a.d, -a.dd}; }
constexpr Jet2 operator*(Jet2 a, Jet2 b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d, a.dd * b.v + 2 * a.d * b.d + a.v * b.dd};
}
constexpr Jet2 operator*(double s, Jet2 a) { return {s * a.v, s * a.d, s * a.dd}; }
constexpr Jet2 operator*(Jet2 a, double s) { return s * a; }
inline Jet2& operator+=(Jet2& a, Jet2 b) { return a = a + b; }

/// f(x) for a jet x, given f, f′, f″ at x.v (chain rule to second order).
constexpr Jet2 Chain(Jet2 x, double f, double f1, double f2) {
  return {f, f1 * x.d, f2 * x.d * x.d + f1 * x.dd};
}

inline Jet2 sin(Jet2 x) {
  const double s = std::sin(x.v), c = std::cos(x.v);
  return Chain(x, s, c, -s);
}
inline Jet2 cos(Jet2 x) {
  const double s = std::sin(x.v), c = std::cos(x.v);
  return Chain(x, c, -s, -c);
}
/// 1/x.
inline Jet2 inv(Jet2 x) {
  const double r = 1.0 / x.v;
  return Chain(x, r, -r * r, 2 * r * r * r);
}
inline Jet2 operator/(Jet2 a, Jet2 b) { return a * inv(b); }
/// 1/√x, for normalising vectors.
inline Jet2 rsqrt(Jet2 x) {
  const double r = 1.0 / std::sqrt(x.v);
  return Chain(x, r, -0.5 * r / x.v, 0.75 * r / (x.v * x.v));
}

}  // namespace hil::truth

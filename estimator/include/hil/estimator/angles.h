#pragma once
/// @file
/// The degree, in radians, for the estimator and guidance (which do not depend on the harness).

#include <numbers>

namespace hil::estimator {

/// Radians per degree: `angle_rad = angle_deg * kDeg`.
inline constexpr double kDeg = std::numbers::pi / 180.0;

}  // namespace hil::estimator

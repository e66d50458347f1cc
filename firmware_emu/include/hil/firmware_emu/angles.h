#pragma once
/// @file
/// The degree, in radians: the one conversion constant of the harness side (truth, emulators,
/// scenario, evaluation). Angles are radians inside; `_deg` names carry degrees at the edges.

#include <numbers>

namespace hil {

/// Radians per degree: `angle_rad = angle_deg * kDeg`.
inline constexpr double kDeg = std::numbers::pi / 180.0;

}  // namespace hil

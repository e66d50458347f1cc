#pragma once
/// @file
/// 2-D ray casting against the primitives of a world map: oriented boxes (ridges, posts) and
/// segments (walls). Everything is in one horizontal frame (the scenario's ENU frame N, metres);
/// heights only decide whether an obstacle is tall enough to block a ray at a given height.
/// Pure geometry, no allocation.

#include <optional>

#include <Eigen/Core>

namespace hil::world {

/// A ray from `origin_m` along the unit vector `dir` (both in the map frame).
struct Ray2 {
  Eigen::Vector2d origin_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d dir = Eigen::Vector2d::UnitX();
};

/// A rectangle of half sizes `half_extent_m` (x along `heading_rad`, y across it) about
/// `centre_m`; `heading_rad` is counter-clockwise from the map x axis.
struct OrientedBox {
  Eigen::Vector2d centre_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d half_extent_m = Eigen::Vector2d::Zero();
  double heading_rad = 0;
};

/// Where a ray meets a primitive: distance along the ray and the outward unit normal there.
struct RayHit {
  double range_m = 0;
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
};

/// The first intersection of `ray` with the box boundary at range in [0, max_range_m]; a ray
/// that starts inside the box hits at range 0 (the sensor is inside the obstacle), with the
/// normal pointing against the ray.
std::optional<RayHit> CastBox(const Ray2& ray, const OrientedBox& box, double max_range_m);

/// The intersection of `ray` with the segment a–b at range in [0, max_range_m] (none when the
/// ray runs parallel to it); the normal faces the ray's origin.
std::optional<RayHit> CastSegment(const Ray2& ray, const Eigen::Vector2d& a_m,
                                  const Eigen::Vector2d& b_m, double max_range_m);

/// Cheap rejection: false when no point within `radius_m` of `centre_m` can be hit at range in
/// [0, max_range_m].
bool MayHitCircle(const Ray2& ray, const Eigen::Vector2d& centre_m, double radius_m,
                  double max_range_m);

/// Where a ray's line crosses a box: entry and exit ranges (the entry is negative when the origin
/// is inside), none when the line misses it or the box lies wholly behind the origin.
struct RaySpan {
  double enter_m = 0, exit_m = 0;
};
std::optional<RaySpan> CrossBox(const Ray2& ray, const OrientedBox& box);

}  // namespace hil::world
